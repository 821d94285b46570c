#include <stdio.h>
#include "tetrec.h"
int main(int argc, char **argv)
{
  (void)argc; (void)argv;
  fprintf(stderr, "tetrec %s: not implemented yet\n", TETREC_VERSION_STRING);
  return 11;
}

/* gen_hard DIR: writes every hard case of hard_cases.h as DIR/<name>.off (all cases are
 * triangle surfaces; coordinates printed with 17 significant digits, which the readers
 * parse with correct rounding, so the files hold exactly the tested doubles) and a
 * manifest DIR/cases.tsv: name, expected outcome (ok:<regions> or the status name),
 * --allow-open needed (0/1), what makes the case hard. */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "hard_cases.h"

int main(int argc, char **argv)
{
  if (argc != 2 || argv[1][0] == '-') {
    fprintf(stderr, "usage: gen_hard DIR   (writes DIR/<case>.off and DIR/cases.tsv)\n");
    return 1;
  }
  const char *dir = argv[1];
  if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
    fprintf(stderr, "gen_hard: cannot create %s: %s\n", dir, strerror(errno));
    return 2;
  }
  char path[4096];
  snprintf(path, sizeof path, "%s/cases.tsv", dir);
  FILE *m = fopen(path, "w");
  if (!m) {
    fprintf(stderr, "gen_hard: cannot write %s: %s\n", path, strerror(errno));
    return 2;
  }
  fprintf(m, "name\texpected\tallow_open\twhy\n");
  int st = 0;
  for (int i = 0; i < hard_case_count(); i++) {
    hard_case c;
    if (hard_case_build(i, &c) != 0) {
      fprintf(stderr, "gen_hard: out of memory building %s\n", hard_case_name(i));
      st = 8;
      break;
    }
    snprintf(path, sizeof path, "%s/%s.off", dir, c.name);
    if (hard_case_write_off(&c, path) != 0) {
      fprintf(stderr, "gen_hard: cannot write %s: %s\n", path, strerror(errno));
      st = 2;
    }
    if (c.status == TR_OK)
      fprintf(m, "%s\tok:%d\t%d\t%s\n", c.name, c.regions, c.allow_open, c.why);
    else
      fprintf(m, "%s\t%s\t%d\t%s\n", c.name, tr_status_name(c.status), c.allow_open, c.why);
    hard_case_free(&c);
  }
  if (fclose(m) != 0)
    st = 2;
  return st;
}

#define _GNU_SOURCE /* wait4 */
/* peer_run: runs one command of the peer benchmark (run.sh) and reports how it ended, its
 * wall time and its peak resident memory, so that no `time` package is needed and both
 * programs are measured the same way: wall time by the monotonic clock around fork/wait,
 * CPU times and peak RSS from the kernel's rusage of the child (wait4).
 *
 * usage: peer_run TIMEOUT_S MEM_MB STDOUT STDERR CMD [ARGS...]
 *   TIMEOUT_S  wall-clock limit; the child's whole process group is killed when it is
 *              reached (0 = none)
 *   MEM_MB     address-space limit of the child (RLIMIT_AS; 0 = none), so a runaway model
 *              fails as out of memory instead of taking the shared machine down
 * Prints one line on stdout:
 *   status=exit:N|signal:N|timeout|exec-failed wall=S user=S sys=S rss_kb=K
 * and exits 0 whenever the measurement itself worked (the child's fate is in the line). */
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static volatile sig_atomic_t expired;

static void on_alarm(int sig)
{
  (void)sig;
  expired = 1;
}

static double now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double tv(struct timeval t)
{
  return (double)t.tv_sec + 1e-6 * (double)t.tv_usec;
}

/* Reopens fd on path (truncated), in the child only. */
static void redirect(int fd, const char *path)
{
  int f = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (f < 0 || dup2(f, fd) < 0)
    _exit(126);
  close(f);
}

int main(int argc, char **argv)
{
  if (argc < 6) {
    fprintf(stderr, "usage: peer_run TIMEOUT_S MEM_MB STDOUT STDERR CMD [ARGS...]\n");
    return 2;
  }
  double timeout = atof(argv[1]);
  long mem_mb = atol(argv[2]);

  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_alarm; /* no SA_RESTART: wait4 must return EINTR on expiry */
  sigaction(SIGALRM, &sa, NULL);

  /* A pipe closed on exec tells the parent whether exec worked. */
  int gate[2];
  if (pipe(gate) < 0 || fcntl(gate[1], F_SETFD, FD_CLOEXEC) < 0) {
    perror("peer_run: pipe");
    return 2;
  }
  double t0 = now();
  pid_t pid = fork();
  if (pid < 0) {
    perror("peer_run: fork");
    return 2;
  }
  if (pid == 0) {
    /* Own process group: a timeout kills everything the command started. */
    setpgid(0, 0);
    close(gate[0]);
    redirect(1, argv[3]);
    redirect(2, argv[4]);
    if (mem_mb > 0) {
      struct rlimit rl = {(rlim_t)mem_mb << 20, (rlim_t)mem_mb << 20};
      setrlimit(RLIMIT_AS, &rl);
    }
    execvp(argv[5], argv + 5);
    char one = 1;
    if (write(gate[1], &one, 1) < 0)
      _exit(127);
    _exit(127);
  }
  setpgid(pid, pid); /* also here: no race with the kill below */
  close(gate[1]);
  char c;
  int exec_failed = read(gate[0], &c, 1) == 1;
  close(gate[0]);

  if (timeout > 0) {
    struct itimerval it;
    memset(&it, 0, sizeof it);
    it.it_value.tv_sec = (time_t)timeout;
    it.it_value.tv_usec = (suseconds_t)((timeout - (double)(time_t)timeout) * 1e6);
    setitimer(ITIMER_REAL, &it, NULL);
  }
  int status = 0, timed_out = 0;
  struct rusage ru;
  memset(&ru, 0, sizeof ru);
  for (;;) {
    pid_t r = wait4(pid, &status, 0, &ru);
    if (r == pid)
      break;
    if (r < 0 && errno == EINTR && expired && !timed_out) {
      timed_out = 1;
      kill(-pid, SIGKILL);
      continue;
    }
    if (r < 0 && errno != EINTR) {
      perror("peer_run: wait4");
      return 2;
    }
  }
  double wall = now() - t0;

  if (exec_failed)
    printf("status=exec-failed");
  else if (timed_out)
    printf("status=timeout");
  else if (WIFEXITED(status))
    printf("status=exit:%d", WEXITSTATUS(status));
  else
    printf("status=signal:%d", WIFSIGNALED(status) ? WTERMSIG(status) : -1);
  printf(" wall=%.3f user=%.3f sys=%.3f rss_kb=%ld\n", wall, tv(ru.ru_utime), tv(ru.ru_stime),
         ru.ru_maxrss);
  return 0;
}

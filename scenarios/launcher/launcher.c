/* The `ferrodyn` command: blocks SIGINT and SIGTERM, then runs the program itself
 * (libexec/ferrodyn/ferrodyn-program beside this file's bin/ folder) with the same arguments.
 *
 * Why: the program loads about 70 shared libraries before its first instruction runs (tens of
 * milliseconds), and a stop signal arriving meanwhile would end it by the default action, before
 * it could leave an interrupted output behind. This launcher, statically linked, blocks the
 * signals within its first instructions; the mask survives exec, so a signal sent meanwhile stays
 * pending until the program has installed its handlers and unblocks it (scenarios/app/
 * terminal.cpp). */
#include <errno.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

int main(int argc, char** argv) {
  sigset_t stop;
  sigemptyset(&stop);
  sigaddset(&stop, SIGINT);
  sigaddset(&stop, SIGTERM);
  sigprocmask(SIG_BLOCK, &stop, NULL);
  (void)argc;

  char self[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
  if (n <= 0) {
    fprintf(stderr, "ferrodyn: cannot locate itself (/proc/self/exe): %s\n", strerror(errno));
    return 127;
  }
  self[n] = '\0';
  char* slash = strrchr(self, '/');
  if (slash != NULL) *slash = '\0';  /* .../bin */
  char program[PATH_MAX];
  if (snprintf(program, sizeof program, "%s/../libexec/ferrodyn/ferrodyn-program", self) >=
      (int)sizeof program) {
    fprintf(stderr, "ferrodyn: installation path too long\n");
    return 127;
  }
  execv(program, argv);
  fprintf(stderr, "ferrodyn: cannot run %s: %s\n", program, strerror(errno));
  return 127;
}

"""What the CLI test scripts share: running the command and counting the expectations that
fail, so that a script reports every failure, not only the first, and exits 1 if any."""
import subprocess
import sys


class Cli:
    def __init__(self, tetrec):
        self.tetrec = tetrec
        self.fails = 0

    def run(self, args, cwd=None):
        """(exit code, stdout, stderr) of `tetrec ARGS` run in cwd."""
        p = subprocess.run([self.tetrec] + args, capture_output=True, text=True, cwd=cwd)
        return p.returncode, p.stdout, p.stderr

    def expect(self, cond, what):
        if not cond:
            print("FAILED:", what, file=sys.stderr)
            self.fails += 1

    def finish(self, name=None):
        if name:
            print("%s: %d failures" % (name, self.fails))
        sys.exit(1 if self.fails else 0)

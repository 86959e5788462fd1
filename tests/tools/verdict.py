"""The pass/fail lines of a scenario test's own checks: each check prints
"  ok: what: detail" or "  FAILED: what: detail"; the test ends with exit()."""
import sys


class Verdict:
    def __init__(self):
        self.ok = True

    def check(self, what, good, detail):
        self.ok &= bool(good)
        print(f"  {'ok' if good else 'FAILED'}: {what}: {detail}")

    def exit(self):
        sys.exit(0 if self.ok else 1)

"""Shared by the scene checks: a list of named assertions, each printed as "ok" or "FAIL", and
the exit status at the end (the checks are run as ctests, which look at the exit status)."""


class Checklist:
    """Collects assertions: ``checks(label, ok)`` prints and records one, ``checks.exit_status()``
    prints the summary and returns 0 if all held, else 1."""

    def __init__(self):
        self.failures = []

    def __call__(self, label, ok):
        print(f"{'ok  ' if ok else 'FAIL'} {label}")
        if not ok:
            self.failures.append(label)

    def exit_status(self):
        print("passed" if not self.failures else f"{len(self.failures)} check(s) failed")
        return 1 if self.failures else 0

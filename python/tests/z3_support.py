"""What the z3 tests share: z3 itself (Debian's python3-z3; the tests that need it skip, saying
so, only where it cannot be imported), the seed, and the tally of z3's answers against
exactccd's."""

import os

import pytest

try:
    import z3
except ImportError:
    z3 = None
needs_z3 = pytest.mark.skipif(
    z3 is None, reason="z3 is not installed: Debian's python3-z3 (.ci/install-deps.sh installs it)")

TIMEOUT_MS = 20000   # per z3 call
MAX_TIMEOUTS = 3     # z3 calls allowed to time out per test


def seed_from_environment():
    seed = int(os.environ.get("EXACTCCD_TEST_SEED", "20240617"), 0)
    print(f"[ seed ] EXACTCCD_TEST_SEED={seed}")
    return seed


class Z3Tally:
    """Counts queries, z3 calls, their timeouts, and the disagreements (messages). A timeout
    counts as neither agreement nor disagreement; more than MAX_TIMEOUTS fail `check`."""

    def __init__(self):
        self.calls = self.timeouts = self.queries = self.contacts = 0
        self.disagreements = []

    def summary(self):
        return (f"{self.queries} queries ({self.contacts} contacts), {self.calls} z3 calls, "
                f"{self.timeouts} timeouts, {len(self.disagreements)} disagreements")

    def record(self, exact, default, where):
        """One query's exact and default answers, which must be the same."""
        self.queries += 1
        self.contacts += exact.collides
        if (default.collides, default.toi_lo, default.toi_hi) != (exact.collides, exact.toi_lo,
                                                                  exact.toi_hi):
            self.disagreements.append(f"{where}: default {default} != exact {exact}")

    def ask(self, expected, answer, where):
        """z3's answer (z3.sat, unsat or unknown) against the expected one."""
        self.calls += 1
        if answer == z3.unknown:
            self.timeouts += 1
        elif answer != expected:
            self.disagreements.append(f"{where}: z3 says {answer}, exactccd {expected}")

    def ask_about(self, exact, decide, where):
        """The three questions of a query exactccd answered with `exact`: contact on the whole
        interval iff exact.collides; for a contact, none before toi_lo and one by toi_hi.
        decide(lo=..., hi=..., hi_strict=...) asks z3 (each keyword optional)."""
        self.ask(z3.sat if exact.collides else z3.unsat, decide(), f"{where} ({exact})")
        if exact.collides:
            if exact.toi_lo > 0:
                self.ask(z3.unsat, decide(hi=exact.toi_lo, hi_strict=True),
                         f"{where} ({exact}) before toi_lo")
            self.ask(z3.sat, decide(hi=exact.toi_hi), f"{where} ({exact}) by toi_hi")

    def check(self):
        print(self.summary())
        assert not self.disagreements, "\n".join([self.summary()] + self.disagreements[:20])
        assert self.timeouts <= MAX_TIMEOUTS, self.summary()

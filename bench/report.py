"""Print each figure beside its target with PASS or MISS, and keep a tally."""

from dataclasses import dataclass, field


@dataclass
class Report:
    """Collects figures; ``line`` prints one, ``summary`` the tally at the end."""

    rows: list[tuple[str, bool | None]] = field(default_factory=list)

    def section(self, title: str) -> None:
        print(f"\n== {title}", flush=True)

    def info(self, name: str, value: str) -> None:
        print(f"  {name:<44} {value}", flush=True)

    def line(self, name: str, value: str, target: str, passed: bool | None) -> None:
        """One figure; ``passed`` None means no verdict (not measured)."""
        verdict = "----" if passed is None else ("PASS" if passed else "MISS")
        print(f"  {name:<44} {value:>16}   target {target:<18} {verdict}", flush=True)
        self.rows.append((name, passed))

    def attack(self, name: str, value: str, held: bool) -> None:
        """An attack run again: "held" when the defence holds, "BROKEN" when it gets
        through (counted as PASS and MISS in the summary)."""
        print(f"  {name:<44} {value:>28}   {'held' if held else 'BROKEN'}", flush=True)
        self.rows.append((name, held))

    def summary(self) -> None:
        passed = [n for n, ok in self.rows if ok]
        missed = [n for n, ok in self.rows if ok is False]
        print(f"\n== Summary: {len(passed)} PASS, {len(missed)} MISS", flush=True)
        for name in missed:
            print(f"  MISS  {name}", flush=True)

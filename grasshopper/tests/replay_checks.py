"""The tally the rhino3dm replays share: each check printed as `ok` or
`FAIL`, and the closing line CI reads."""

counts = {"passed": 0, "failed": 0}


def check(name, condition, detail=""):
    if condition:
        counts["passed"] += 1
        print(f"ok   {name}")
    else:
        counts["failed"] += 1
        print(f"FAIL {name}{': ' + detail if detail else ''}")


def finish(title):
    """Prints `title: N passed, N failed` and gives the exit code."""
    print(f"{title}: {counts['passed']} passed, {counts['failed']} failed")
    return 0 if counts["failed"] == 0 else 1

"""The runner of the script tests in this folder: each check is a function test_* of the calling module; all
of them run, one line each, then "N passed, M failed"; the exit status is nonzero if any failed."""


def run_all(namespace):
    tests = [(n, f) for n, f in sorted(namespace.items()) if n.startswith("test_") and callable(f)]
    failed = 0
    for name, f in tests:
        try:
            f()
            print("PASS", name)
        except Exception as e:  # noqa: BLE001 - report every failure
            failed += 1
            print("FAIL", name, repr(e))
    print(f"{len(tests) - failed} passed, {failed} failed")
    return 1 if failed else 0

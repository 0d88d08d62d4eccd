"""Loads each library given with the add-on's native.load, in a process of its own: a damaged
library that reached ctypes could kill the process (SIGBUS), which must fail the test that ran
this rather than the test runner. Run by test_robustness.py with the add-on enabled:

    load_library.py PATH...

Prints 'EDGELIGHT_LOAD <index> ok' or 'EDGELIGHT_LOAD <index> refused <status>: <message>'.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import helpers  # noqa: E402

native = helpers.addon().bridge.native
for i, path in enumerate(sys.argv[sys.argv.index("--") + 1:]):
    try:
        native.load(path)
        print(f"EDGELIGHT_LOAD {i} ok", flush=True)
    except native.LibraryUnavailable as e:
        print(f"EDGELIGHT_LOAD {i} refused {e}", flush=True)

"""Runs the add-on tests inside real Blender:

    blender -b --factory-startup --addons edgelight --python tests/blender/runner.py [-- -k PATTERN]

Prints one line 'blender X.Y: N passed, N failed, N skipped' and exits non-zero on any failure.
"""
import os
import sys
import unittest

import bpy

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)


def main():
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    loader = unittest.TestLoader()
    patterns = [f"*{args[i + 1]}*" for i, a in enumerate(args[:-1]) if a == "-k"]
    if patterns:
        loader.testNamePatterns = patterns
    suite = loader.discover(HERE, pattern="test_*.py")
    result = unittest.TextTestRunner(verbosity=2, stream=sys.stdout).run(suite)
    failed = len(result.failures) + len(result.errors)
    passed = result.testsRun - failed - len(result.skipped)
    print(f"blender {bpy.app.version_string}: {passed} passed, {failed} failed, {len(result.skipped)} skipped")
    sys.stdout.flush()
    os._exit(0 if failed == 0 and result.testsRun > 0 else 1)


main()

"""The frame of a scripted session in Blender's UI (viewport_session.py, docs_session.py): checks
recorded as they pass or fail, the steps run one per timer tick so that Blender draws between
them, and the process ended with the result (exit 1 on any failure or none at all)."""
import os
import traceback

import bpy

results = []


def check(name, ok, detail=""):
    results.append((name, bool(ok), detail))
    print(f"{'PASS' if ok else 'FAIL'} {name} {detail}", flush=True)


def run(steps, label):
    """Runs the generator function `steps` from a timer (each `yield` returns the seconds until
    the next step); prints "<label>: N passed, M failed" and exits when it ends or raises."""
    gen = steps()

    def tick():
        try:
            return next(gen)
        except StopIteration:
            finish(label)
        except Exception:
            traceback.print_exc()
            check("session ran to the end", False)
            finish(label)
        return None

    bpy.app.timers.register(tick, first_interval=1.0)


def finish(label):
    failed = sum(1 for _, ok, _ in results if not ok)
    print(f"{label}: {len(results) - failed} passed, {failed} failed", flush=True)
    os._exit(1 if failed or not results else 0)

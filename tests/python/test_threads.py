"""Long calls release the GIL: Python runs while a render runs, renders of one mesh from several
threads agree, progress reaches a callback, and Ctrl-C raises KeyboardInterrupt."""
import os
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np

import inversevis


def test_python_runs_while_a_render_runs_on_another_thread():
    mesh = inversevis.Mesh.read("scene:vessel-tree")
    inversevis.render(mesh, "inversevis", size=(40, 40))  # the volume built before timing
    done = threading.Event()
    result = {}

    def work():
        result["picture"] = inversevis.render(mesh, "inversevis", size=(500, 500), full_trace=True)
        done.set()

    worker = threading.Thread(target=work)
    worker.start()
    ticks = 0
    while not done.is_set():
        ticks += 1  # the main thread holds the GIL here: it runs only while render() releases it
    worker.join()
    assert ticks > 100000, ticks
    assert result["picture"].rgba.shape[0] == 500


def test_renders_of_one_mesh_from_two_threads_agree():
    mesh = inversevis.Mesh.read("scene:vessel-tree")
    pictures = [None, None]

    def work(k):
        pictures[k] = inversevis.render(mesh, size=(150, 150), theta=80, phi=40 * k)

    threads = [threading.Thread(target=work, args=(k,)) for k in (0, 1)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    again = [inversevis.render(mesh, size=(150, 150), theta=80, phi=40 * k) for k in (0, 1)]
    for k in (0, 1):
        assert np.array_equal(pictures[k].rgba, again[k].rgba)
    assert not np.array_equal(again[0].rgba, again[1].rgba)


def test_progress_reaches_the_callback_and_its_exception_stops_the_render():
    mesh = inversevis.Mesh.read("scene:vessel-tree")
    seen = []
    inversevis.render(mesh, "inversevis", size=(100, 100), progress=lambda stage, percent: seen.append((stage, percent)))
    assert ("render", 100) in seen or any(stage == "render" for stage, _ in seen)

    def stop(stage, percent):
        if percent > 20:
            raise RuntimeError("enough")

    try:
        inversevis.render(mesh, "inversevis", size=(300, 300), full_trace=True, progress=stop)
    except RuntimeError as e:
        assert "enough" in str(e)
    else:
        raise AssertionError("the callback's exception did not stop the render")


def test_ctrl_c_raises_keyboard_interrupt_within_a_second(tmp_path):
    script = textwrap.dedent(f"""
        import os, signal, threading, time, inversevis
        mesh = inversevis.Mesh.read("scene:vessel-tree")
        inversevis.render(mesh, "inversevis", size=(20, 20))
        threading.Timer(1.0, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
        start = time.monotonic()
        try:
            inversevis.render(mesh, size=(3000, 3000), full_trace=True).save({str(tmp_path / "p.png")!r})
        except KeyboardInterrupt:
            print("interrupted after", time.monotonic() - start)
        else:
            print("finished")
    """)
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=dict(os.environ), timeout=300)
    assert done.returncode == 0, done.stderr
    words = done.stdout.split()
    assert words[0] == "interrupted", done.stdout
    # The signal at 1 s; the render alone takes half a minute or more. Stopped within a second or so
    # (measured 1.4-1.7 s), allowing for a loaded 2-core machine (2.8 s seen beside the viewer's tests).
    assert float(words[-1]) < 5.0
    assert not (tmp_path / "p.png").exists()

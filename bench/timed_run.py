"""Runs a command and prints its wall seconds and peak resident memory as JSON (scripts/bench.sh).

    python3 bench/timed_run.py OUT.json COMMAND [ARG...]

The command's own output goes to stderr; OUT.json is written under a temporary name and renamed,
only when the command succeeds (its exit status is passed on)."""
import json
import os
import resource
import subprocess
import sys
import time

if len(sys.argv) < 3:
    sys.exit("usage: timed_run.py OUT.json COMMAND [ARG...]")
out, command = sys.argv[1], sys.argv[2:]
start = time.perf_counter()
status = subprocess.run(command, stdout=sys.stderr).returncode
wall = time.perf_counter() - start
if status != 0:
    sys.exit(status)
peak_kib = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss  # Linux: KiB, the largest child
with open(out + ".tmp", "w") as f:
    json.dump({"command": command, "wall_seconds": wall, "peak_rss_bytes": peak_kib * 1024}, f)
os.replace(out + ".tmp", out)

#!/usr/bin/env python3
"""The Jupyter kernel's start-up: wall time from launching
`chasles kernel --connection-file F` to its kernel_info_reply on the shell
socket (LANGUAGE.md §13; the target is under 100 ms).

usage: benches/kernel_startup.py [BINARY] [RUNS]
  BINARY defaults to target/release/chasles; RUNS to 20.
Needs pyzmq (tests/jupyter/requirements.txt; .ci/run installs it into
target/jupyter-venv: target/jupyter-venv/bin/python benches/kernel_startup.py).
"""

import hashlib
import hmac
import json
import os
import socket
import statistics
import subprocess
import sys
import tempfile
import time
import uuid

import zmq


def free_ports(n):
    socks = [socket.socket() for _ in range(n)]
    for s in socks:
        s.bind(("127.0.0.1", 0))
    ports = [s.getsockname()[1] for s in socks]
    for s in socks:
        s.close()
    return ports


def one(binary, ctx):
    shell, iopub, stdin, control, hb = free_ports(5)
    key = uuid.uuid4().hex
    info = dict(transport="tcp", ip="127.0.0.1", shell_port=shell, iopub_port=iopub,
                stdin_port=stdin, control_port=control, hb_port=hb, key=key,
                signature_scheme="hmac-sha256", kernel_name="chasles")
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(info, f)
        path = f.name
    sock = ctx.socket(zmq.DEALER)
    sock.setsockopt(zmq.RECONNECT_IVL, 1)
    sock.setsockopt(zmq.LINGER, 0)
    session = uuid.uuid4().hex
    header = json.dumps(dict(msg_id=uuid.uuid4().hex, username="bench", session=session,
                             date="2026-01-01T00:00:00Z", msg_type="kernel_info_request",
                             version="5.3")).encode()
    parts = [header, b"{}", b"{}", b"{}"]
    sig = hmac.new(key.encode(), b"".join(parts), hashlib.sha256).hexdigest().encode()
    started = time.perf_counter()
    proc = subprocess.Popen([binary, "kernel", "--connection-file", path],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        sock.connect(f"tcp://127.0.0.1:{shell}")
        sock.send_multipart([b"<IDS|MSG>", sig] + parts)
        if not sock.poll(5000):
            raise SystemExit("no kernel_info_reply within 5 s")
        reply = sock.recv_multipart()
        elapsed = time.perf_counter() - started
        content = json.loads(reply[reply.index(b"<IDS|MSG>") + 5])
        assert content["language_info"]["file_extension"] == ".chs", content
        return elapsed
    finally:
        proc.kill()
        proc.wait()
        sock.close()
        os.unlink(path)


def main():
    binary = sys.argv[1] if len(sys.argv) > 1 else "target/release/chasles"
    runs = int(sys.argv[2]) if len(sys.argv) > 2 else 20
    ctx = zmq.Context()
    times = [one(binary, ctx) * 1000 for _ in range(runs)]
    times.sort()
    print(f"kernel_info_reply after launch, {runs} runs of {binary}:")
    print(f"  median {statistics.median(times):.1f} ms, min {times[0]:.1f} ms, "
          f"max {times[-1]:.1f} ms (target: under 100 ms)")
    return 0 if statistics.median(times) < 100 else 1


if __name__ == "__main__":
    sys.exit(main())

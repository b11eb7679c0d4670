"""What the pyserial tests of servodesk-sim share: the simulator as a child process, and reading a port up to
a marker. Real time over a pty or the loopback: the bounds are generous (the simulator may get a sliver of a
loaded machine); a pass takes milliseconds."""
import contextlib
import subprocess
import time


@contextlib.contextmanager
def simulator(sim, *args):
    """servodesk-sim with args; yields its first line ("PTY /dev/pts/N", "TCP 127.0.0.1:PORT")."""
    proc = subprocess.Popen([sim, *args], stdout=subprocess.PIPE)
    try:
        yield proc.stdout.readline().decode().strip()
    finally:
        proc.terminate()
        proc.wait(5)


def read_until(port, marker, timeout_s=30.0):
    """What the port sends up to and including marker (never past it: the rest is the next read's)."""
    data = b""
    deadline = time.monotonic() + timeout_s
    while marker not in data and time.monotonic() < deadline:
        data += port.read(1)
    if marker not in data:
        raise AssertionError(f"did not see {marker!r}; got {data!r}")
    return data

"""What the pyserial tests of servodesk-sim share: the simulator as a child process, and reading a port up to
a marker. Real time over a pty or the loopback: the bounds are generous (the simulator may get a sliver of a
loaded machine); a pass takes milliseconds."""
import contextlib
import socket
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


def bench(path, line):
    """One bench command on servodesk-sim's --control socket at path; its one-line answer."""
    with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as s:
        s.settimeout(30)
        s.connect(path)
        s.sendall(line.encode() + b"\n")
        answer = b""
        while not answer.endswith(b"\n"):
            answer += s.recv(256)
        return answer.decode().strip()


def refused(sim, drive, axes):
    """servodesk-sim with a bad --axes list: its exit code and what it said on stderr."""
    out = subprocess.run([sim, "--drive", drive, "--axes", axes, "--pty"], capture_output=True, text=True,
                         timeout=60)
    return out.returncode, out.stderr

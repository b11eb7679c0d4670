#!/usr/bin/python3
"""servodesk-sim --control: a test flips I1 through the control socket while it talks to the drive on its
pty, and the drive sees it (P I1), a tripped limit switch faults an enabled drive, and bad commands are
answered with ERROR."""
import os
import socket
import subprocess
import sys
import tempfile
import time

import serial  # Debian's python3-serial


# A real pty peer needs real time: the bound is generous (30 s for a few characters) because the simulator
# may get a sliver of a loaded machine (one was seen to stall every process for 8 s); a pass takes ms.
def read_until(port, marker, timeout_s=30.0):
    data = b""
    deadline = time.monotonic() + timeout_s
    while marker not in data and time.monotonic() < deadline:
        data += port.read(1)  # never past the marker: what follows it is the next read_until's
    if marker not in data:
        raise AssertionError(f"did not see {marker!r}; got {data!r}")
    return data


class Control:
    def __init__(self, path):
        self.sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        deadline = time.monotonic() + 5
        while True:
            try:
                self.sock.connect(path)
                break
            except OSError:
                if time.monotonic() > deadline:
                    raise
                time.sleep(0.05)
        self.sock.settimeout(5)
        self.buffer = b""

    def command(self, line):
        self.sock.sendall(line.encode() + b"\n")
        while b"\n" not in self.buffer:
            chunk = self.sock.recv(4096)
            if not chunk:
                raise AssertionError("control socket closed")
            self.buffer += chunk
        answer, self.buffer = self.buffer.split(b"\n", 1)
        return answer.decode()


def ask(port, command):
    port.write(command.encode() + b"\r")
    return read_until(port, b"\r\n-->")


def main(sim):
    passed = 0
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "bds5.sock")
        proc = subprocess.Popen([sim, "--drive", "bds5", "--pty", "--control", path], stdout=subprocess.PIPE)
        try:
            first = proc.stdout.readline().decode().strip()
            assert first.startswith("PTY /dev/"), first
            second = proc.stdout.readline().decode().strip()
            assert second == f"CONTROL {path}", second
            control = Control(path)
            with serial.Serial(first[4:], 9600, timeout=0.2) as port:
                read_until(port, b"\r\n-->")
                assert ask(port, "P I1") == b"P I1\r\n           0\r\n-->"
                assert control.command("input 1 on") == "OK"
                time.sleep(0.05)
                answer = ask(port, "P I1")
                assert answer == b"P I1\r\n           1\r\n-->", answer
                passed += 1

                status = control.command("status")
                assert status.startswith("inputs=1000000000000000 "), status
                assert " motor=REF-MEDIUM" in status, status
                passed += 1

                ask(port, "EN")
                assert ask(port, "P ACTIVE") == b"P ACTIVE\r\n           1\r\n-->"
                assert control.command("limits on off") == "OK"
                time.sleep(0.05)
                port.write(b"\r")
                answer = read_until(port, b"HARDWARE OVERTRAVEL")
                assert b"\x07ERR 24" in answer, answer
                read_until(port, b"-->")
                assert ask(port, "P ACTIVE") == b"P ACTIVE\r\n           0\r\n-->"
                passed += 1

                assert control.command("input 99 on").startswith("ERROR "), "out of range"
                assert control.command("fly me to the moon") == "ERROR unknown command fly"
                passed += 1
        finally:
            proc.terminate()
            proc.wait(5)
        assert not os.path.exists(path), "the socket file is removed at exit"
    print(f"servodesk-sim control socket: {passed} passed, 0 failed")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))

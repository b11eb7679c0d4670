#!/usr/bin/python3
"""A client nobody here wrote (pyserial) talks to servodesk-sim --pty like a terminal program would."""
import subprocess
import sys
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


def main(sim):
    proc = subprocess.Popen([sim, "--drive", "bds5", "--pty"], stdout=subprocess.PIPE)
    try:
        first = proc.stdout.readline().decode().strip()
        assert first.startswith("PTY /dev/"), first
        with serial.Serial(first[4:], 9600, timeout=0.2) as port:
            # The drive signs on as it powers up, whether or not a terminal is open yet: what was sent before
            # the port opened is gone (as with a real drive), so the sign-on seen is its tail, or nothing.
            signon = b""
            deadline = time.monotonic() + 3.0
            while not signon and time.monotonic() < deadline:
                signon = port.read(1)
            if signon:
                signon += read_until(port, b"\r\n-->")
            full = b"BDS5 DIGITAL SERVO DRIVE  V3.0.0  (SERVODESK SIMULATION)\r\n-->"
            if signon.endswith(b"\r\n-->"):
                assert full.endswith(signon.lstrip(b"\r\n")), signon
            else:
                assert signon == b"", signon
                port.write(b"\r")
                assert read_until(port, b"\r\n-->") == b"\r\n-->"
            port.write(b'P "HELLO, WORLD"\r')
            answer = read_until(port, b"HELLO, WORLD\r\n-->")
            assert answer == b'P "HELLO, WORLD"\r\nHELLO, WORLD\r\n-->', answer
            port.write(b"X1=1000\r")
            assert read_until(port, b"\r\n-->") == b"X1=1000\r\n-->"
            port.write(b"P X1\r")
            answer = read_until(port, b"\r\n-->")
            assert answer == b"P X1\r\n        1000\r\n-->", answer
            port.write(b"BOGUS\r")
            answer = read_until(port, b"INVALID INSTRUCTION\r\n-->")
            assert b"\x07ERR 80 'BOGUS'" in answer, answer
    finally:
        proc.terminate()
        proc.wait(5)
    print("pyserial client: 4 passed, 0 failed")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))

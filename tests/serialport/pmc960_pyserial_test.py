#!/usr/bin/python3
"""pyserial talks to servodesk-sim --drive pmc960 --pty like a terminal or a host program would: the prompt,
echo, an error code, a status poll and the communications checksum."""
import subprocess
import sys
import time

import serial  # Debian's python3-serial

PROMPT = b"\r\n=}"


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
    proc = subprocess.Popen([sim, "--drive", "pmc960", "--pty"], stdout=subprocess.PIPE)
    passed = 0
    try:
        first = proc.stdout.readline().decode().strip()
        assert first.startswith("PTY /dev/"), first
        with serial.Serial(first[4:], 9600, timeout=0.2) as port:
            time.sleep(0.3)
            port.reset_input_buffer()
            port.write(b"\r")
            assert read_until(port, PROMPT) == PROMPT
            passed += 1
            port.write(b"A3500\r")
            assert read_until(port, PROMPT) == b"A3500" + PROMPT
            port.write(b"A?")
            answer = read_until(port, PROMPT)
            assert answer == b"A?3500" + PROMPT, answer
            passed += 1
            port.write(b"W")
            answer = read_until(port, PROMPT)
            assert answer == b"W#A1" + PROMPT, answer
            passed += 1
            port.write(b"\x1dg")
            answer = read_until(port, b"\r")
            assert answer == b"0\r", answer
            passed += 1
            port.write(b"\x1dh")
            read_until(port, b"\r")  # reset the checksum
            block = b"V200\r"
            port.write(block)
            read_until(port, PROMPT)
            port.write(b"\x1dh")
            answer = read_until(port, b"\r")
            assert answer == str(sum(block) % 65536).encode() + b"\r", answer
            passed += 1
    finally:
        proc.terminate()
        proc.wait(5)
    print(f"pyserial pmc960 client: {passed} passed, 0 failed")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))

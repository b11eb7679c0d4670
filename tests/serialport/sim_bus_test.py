#!/usr/bin/python3
"""servodesk-sim --axes (issue 21): four simulated BDS5s on one multidrop line behind a pty, with a client
nobody here wrote (pyserial). As the manual's multidrop section has it (L5416-5469, L10013-10038): all asleep
at power-up, '\\' + ID wakes one and only it answers, each axis keeps its own variables, a broadcast reaches
every axis and none answers it; the bench's socket picks the axis it reaches; servodesk-cli --axis talks to
one axis, and machine scan lists the axes on the line."""
import os
import subprocess
import sys
import tempfile

import serial  # Debian's python3-serial

from sim_client import bench, read_until, simulator


def main(sim, cli_path):
    control = os.path.join(tempfile.mkdtemp(), "bench")
    passed = 0
    with simulator(sim, "--drive", "bds5", "--axes", "A,B,C,D", "--pty", "--control", control) as first:
        assert first.startswith("PTY /dev/"), first
        with serial.Serial(first[4:], 9600, timeout=0.2) as port:
            # Asleep at power-up: the CR gets nothing, so B's prompt is the first thing on the line.
            port.write(b"\r\\B")
            assert read_until(port, b"B->") == b"\r\nB->"
            passed += 1
            port.write(b"X1=5\r")
            assert read_until(port, b"\r\nB->") == b"X1=5\r\nB->"
            port.write(b"\\A")
            assert read_until(port, b"A->") == b"\r\nA->"
            port.write(b"P X1\r")
            answer = read_until(port, b"\r\nA->")
            assert answer == b"P X1\r\n           0\r\nA->", answer  # A is another drive
            passed += 1
            # '\\' puts every axis to sleep, '\\*' broadcasts: all execute, none answers.
            port.write(b"\\\\*X2=7\r\\D")
            assert read_until(port, b"D->") == b"\r\nD->"
            port.write(b"P X2\r")
            answer = read_until(port, b"\r\nD->")
            assert answer == b"P X2\r\n           7\r\nD->", answer
            passed += 1
            # The bench reaches the axis picked: C's input 1, read by C and not by D.
            assert bench(control, "axis C") == "OK"
            assert bench(control, "input 1 on") == "OK"
            port.write(b"P I1\r")
            assert read_until(port, b"\r\nD->") == b"P I1\r\n           0\r\nD->"
            port.write(b"\\C")
            read_until(port, b"C->")
            port.write(b"P I1\r")
            assert read_until(port, b"\r\nC->") == b"P I1\r\n           1\r\nC->"
            assert bench(control, "axis Q").startswith("ERROR")
            # The electronic line shaft: A's encoder output into D's master input; a bad pair is refused.
            assert bench(control, "line-shaft A D") == "OK"
            assert bench(control, "line-shaft A Q") == "ERROR no axis Q on this line"
            assert bench(control, "line-shaft off") == "OK"
            passed += 1
        # servodesk-cli --axis wakes the axis it names and talks to it alone; an ID not on the line is said.
        def cli(*args):
            return subprocess.run([cli_path, "--port", first[4:], *args], capture_output=True, text=True, timeout=120)
        out = cli("--axis", "A", "send", "P X1")
        assert out.returncode == 0 and out.stdout.split() == ["0"], (out.returncode, out.stdout, out.stderr)
        out = cli("--axis", "B", "send", "P X1", "X3=9")
        assert out.returncode == 0 and out.stdout.split() == ["5"], (out.returncode, out.stdout, out.stderr)
        out = cli("--axis", "Q", "send", "P X1")
        assert out.returncode == 3 and "axis Q" in out.stderr, (out.returncode, out.stderr)
        passed += 1
        # machine scan: one line per axis that answers, in ID order; E is not on the line. (An answer is
        # credited to the ID in its prompt, so the wait only bounds how long an absent ID takes.)
        out = cli("machine", "scan", "--ids", "E,D,C,B,A", "--wait", "5000")
        assert out.returncode == 0, (out.returncode, out.stdout, out.stderr)
        assert out.stdout.splitlines() == [f"{a} BDS5 interactive {a}->" for a in "ABCD"], out.stdout
        assert "4 axes answered of 5 IDs called" in out.stderr, out.stderr
        out = cli("--axis", "C", "send", "P X2")  # the scan left the line asleep, and C answers when called
        assert out.returncode == 0 and out.stdout.split() == ["7"], (out.returncode, out.stdout, out.stderr)
        passed += 1
    print(f"sim --axes: {passed} passed, 0 failed")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))

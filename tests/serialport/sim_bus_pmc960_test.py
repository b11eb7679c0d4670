#!/usr/bin/python3
"""servodesk-sim --drive pmc960 --axes (issue 21): two simulated PMC-960s, THI IDs A and B, on one RS-422 line
behind a pty, with pyserial typing MPL. As the attention-character section has it (L2537-2568): all listen
at power-up (drive_core/pmc960/DECISIONS.md), <attn> ID (1DH + ID) makes one the talker and only it echoes,
prompts and answers polls, each keeps its own registers and communications checksum, selecting another
silences the first; the bench's socket picks the axis it reaches; a bad ID list is refused with the reason.

Silence is shown by order, not by waiting: every answer is read up to its end and must be exactly what the
talker sends, so bytes from an axis that should be silent would stand in front of the next answer."""
import os
import sys
import tempfile

import serial  # Debian's python3-serial

from sim_client import bench, read_until, refused, simulator

ATTN = b"\x1d"


def main(sim):
    control = os.path.join(tempfile.mkdtemp(), "bench")
    passed = 0
    with simulator(sim, "--drive", "pmc960", "--axes", "A,B", "--pty", "--control", control) as first:
        assert first.startswith("PTY /dev/"), first
        with serial.Serial(first[4:], 9600, timeout=0.2) as port:
            def ask(request, answer, end):
                port.write(request)
                got = read_until(port, end)
                assert got == answer, (request, got, answer)

            # Listeners at power-up: the first CR gets nothing, so B's prompt is the first thing on the line.
            port.write(b"\r")
            ask(ATTN + b"B\r", b"\r\nB}", b"}")
            ask(ATTN + b"A\r", b"\r\nA}", b"}")
            passed += 1
            # Each axis is a drive of its own.
            ask(b"A3500\r", b"A3500\r\nA}", b"\r\nA}")
            ask(ATTN + b"BA?", b"A?4000\r\nB}", b"\r\nB}")
            ask(ATTN + b"AA?", b"A?3500\r\nA}", b"\r\nA}")
            passed += 1
            # Polls reach the talker alone, and each counted only what it read as the talker (digest 4.8):
            # B the CR that selected it and "A?", A its CR, "A3500" CR and "A?".
            ask(ATTN + b"B" + ATTN + b"h", str(sum(b"\rA?")).encode() + b"\r", b"\r")
            ask(ATTN + b"A" + ATTN + b"h", str(sum(b"\rA3500\rA?")).encode() + b"\r", b"\r")
            passed += 1
            # Selecting another silences the first: nobody is ID '=' now, so nobody echoes or prompts.
            port.write(ATTN + b"=A?\r")
            ask(ATTN + b"B\r", b"\r\nB}", b"}")
            passed += 1
            assert bench(control, "axis B") == "OK"
            assert bench(control, "axis a").startswith("ERROR")
            passed += 1
    for axes, reason in (("A,a", "is not a PMC-960 axis ID"), ("A,AB", "L1918"),
                         ("B,B", "axis ID B is on the bus twice")):
        code, said = refused(sim, "pmc960", axes)
        assert code == 2 and reason in said, (axes, code, said)
    passed += 1
    print(f"sim --drive pmc960 --axes: {passed} passed, 0 failed")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))

#!/usr/bin/python3
"""servodesk-sim --drive sc750 --axes (issue 21): three simulated SC750s, addresses 1, 2 and 17, on one
multidrop line behind a pty, with pyserial speaking Motion Dialogue's frames (drive_core/sc750/PROTOCOL.md).
As Appendix C has it (L3676-3734): all logged off at power-up, "/nnn" logs one on and only it answers, each
axis keeps its own variables, logging on another silences the first; the bench's socket picks the axis it
reaches; a bad address list is refused with the manual's reason.

Silence is shown by order, not by waiting: every answer is read up to its end and must be exactly the one
frame expected, so a frame from an axis that should be silent would stand in front of the next answer."""
import os
import sys
import tempfile

import serial  # Debian's python3-serial

from sim_client import bench, read_until, refused, simulator


def frame(letter, payload=""):
    """SOH, letter, payload, two hex digits of (letter + payload) mod 256, CR."""
    body = (letter + payload).encode()
    return b"\x01" + body + b"%02X" % (sum(body) % 256) + b"\r"


def main(sim):
    control = os.path.join(tempfile.mkdtemp(), "bench")
    passed = 0
    with simulator(sim, "--drive", "sc750", "--axes", "1,2,17", "--pty", "--control", control) as first:
        assert first.startswith("PTY /dev/"), first
        with serial.Serial(first[4:], 9600, timeout=0.2) as port:
            def ask(request, answer):
                port.write(request)
                got = read_until(port, b"\r")
                assert got == answer, (request, got, answer)

            # Logged off at power-up: the status request gets nothing, so 2's answer is the first on the line.
            port.write(frame("?"))
            ask(b"/002" + frame("G", "AXIS.ADDR"), frame("G", "AXIS.ADDR=2"))
            ask(b"/17," + frame("G", "AXIS.ADDR"), frame("G", "AXIS.ADDR=17"))  # ended by a non-digit
            ask(frame("V"), frame("V", "752,2.8,1,17"))
            passed += 1
            # Each axis is a drive of its own.
            ask(b"/001" + frame("P", "RUN.SPEED=500"), frame("P", "RUN.SPEED=500"))
            ask(b"/002" + frame("G", "RUN.SPEED"), frame("G", "RUN.SPEED=1000"))
            ask(b"/001" + frame("G", "RUN.SPEED"), frame("G", "RUN.SPEED=500"))
            passed += 1
            # Logging on another silences the first (L3714): 1 does not answer with 17, nor 17 with 1.
            ask(b"/017" + frame("G", "LOGGEDON"), frame("G", "LOGGEDON=1"))
            ask(b"/001" + frame("G", "LOGGEDON"), frame("G", "LOGGEDON=1"))
            ask(b"/017" + frame("G", "AXIS.ADDR"), frame("G", "AXIS.ADDR=17"))
            port.write(b"/003" + frame("G", "AXIS.ADDR"))  # no unit 3: every transmitter is off
            ask(b"/001" + frame("G", "AXIS.ADDR"), frame("G", "AXIS.ADDR=1"))
            passed += 1
            # The bench reaches the axis picked: 17's input 3, read by 17 and not by 1.
            assert bench(control, "axis 17") == "OK"
            assert bench(control, "input 3 off") == "OK"
            ask(frame("G", "INP3"), frame("G", "INP3=1"))
            ask(b"/017" + frame("G", "INP3"), frame("G", "INP3=0"))
            assert bench(control, "axis 3").startswith("ERROR")
            passed += 1
    for axes, reason in (("1,255", "is not an SC750 multidrop address"), ("1,07", "L3708"),
                         ("4,4", "axis ID 4 is on the bus twice")):
        code, said = refused(sim, "sc750", axes)
        assert code == 2 and reason in said, (axes, code, said)
    passed += 1
    print(f"sim --drive sc750 --axes: {passed} passed, 0 failed")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))

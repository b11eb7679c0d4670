#!/usr/bin/python3
"""servodesk-sim --drive pmc960 --overrun: bytes sent back to back after a motion trigger overrun the
controller's one-character receive buffer (J100+;<cr>: the ';' and its } handshake are lost); without
--overrun the same bytes all arrive."""
import subprocess
import sys


def run(sim, *extra):
    return subprocess.run([sim, "--drive", "pmc960", "--stdio", *extra], input=b"SM2\rJ100+;\r",
                          capture_output=True, timeout=20).stdout


def main(sim):
    plain = run(sim)
    assert b"J100+;}" in plain, plain
    overrun = run(sim, "--overrun")
    assert b"J100+\r\n=}" in overrun, overrun
    assert b";" not in overrun, overrun
    refused = subprocess.run([sim, "--drive", "bds5", "--stdio", "--overrun"], input=b"", capture_output=True,
                             timeout=20)
    assert refused.returncode == 2 and b"pmc960 only" in refused.stderr, refused
    print("3 checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))

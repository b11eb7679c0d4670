#!/usr/bin/python3
"""servodesk-sim --tcp as a serial device server, with clients nobody here wrote (issue 21): pyserial's
rfc2217:// client (Telnet Com Port Control: it negotiates and sets 9600 8N1 before any data) and its raw
socket:// client talk to the simulated BDS5; a second client while one is connected is turned away; and
servodesk-cli reaches the drive with --port rfc2217://... and --port tcp://...."""
import socket
import subprocess
import sys
import time

import serial  # Debian's python3-serial

from sim_client import read_until, simulator




def talk(port):
    """A prompt, a print and a variable, as a terminal user would type them."""
    port.write(b"\r")
    read_until(port, b"\r\n-->")
    port.write(b'P "HELLO, WORLD"\r')
    answer = read_until(port, b"HELLO, WORLD\r\n-->")
    assert answer.endswith(b'P "HELLO, WORLD"\r\nHELLO, WORLD\r\n-->'), answer
    port.write(b"X1=1000\r")
    read_until(port, b"X1=1000\r\n-->")
    port.write(b"P X1\r")
    answer = read_until(port, b"1000\r\n-->")
    assert answer.endswith(b"P X1\r\n        1000\r\n-->"), answer


def main(sim, cli):
    passed = 0
    with simulator(sim, "--drive", "bds5", "--tcp", "0") as first:
        assert first.startswith("TCP 127.0.0.1:"), first
        port_number = int(first.rsplit(":", 1)[1])
        # RFC 2217: pyserial's open() fails unless the server negotiates the option and accepts 9600 8N1.
        with serial.serial_for_url(f"rfc2217://127.0.0.1:{port_number}", baudrate=9600, timeout=0.2) as port:
            talk(port)
            passed += 1
            # One host a line: a second connection is closed at once, and the first carries on.
            with socket.create_connection(("127.0.0.1", port_number), timeout=30) as second:
                assert second.recv(16) == b"", "a second client was served"
            passed += 1
            port.write(b"P X1\r")
            assert read_until(port, b"1000\r\n-->").endswith(b"1000\r\n-->")
        # Raw TCP, once the first client has gone: the drive kept its variables (it never powered down).
        deadline = time.monotonic() + 30
        while True:
            try:
                port = serial.serial_for_url(f"socket://127.0.0.1:{port_number}", timeout=0.2)
                port.write(b"P X1\r")
                answer = read_until(port, b"\r\n-->", timeout_s=1.0)
                break
            except (AssertionError, serial.SerialException):  # the server has not seen the first one go yet
                if time.monotonic() > deadline:
                    raise
        with port:
            assert answer.endswith(b"P X1\r\n        1000\r\n-->"), answer
            talk(port)
        passed += 1
        for scheme in ("rfc2217", "tcp"):
            out = subprocess.run([cli, "--port", f"{scheme}://127.0.0.1:{port_number}", "send", "P X1"],
                                 capture_output=True, text=True, timeout=120)
            assert out.returncode == 0, (scheme, out.returncode, out.stdout, out.stderr)
            assert "1000" in out.stdout, (scheme, out.stdout)
            passed += 1
        out = subprocess.run([cli, "--port", "tcp://127.0.0.1", "send", "P X1"], capture_output=True, text=True,
                             timeout=60)
        assert out.returncode == 2 and "tcp://HOST:PORT" in out.stderr, (out.returncode, out.stderr)
        passed += 1
    print(f"sim --tcp: {passed} passed, 0 failed")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))

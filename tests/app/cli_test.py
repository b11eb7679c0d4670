#!/usr/bin/python3
"""servodesk-cli against the simulated drive (--sim) and through a real pty (servodesk-sim --pty): every
command, the failure paths and the exit codes. Usage: cli_test.py BIN_DIR"""
import os
import subprocess
import sys
import tempfile

BIN = sys.argv[1]
CLI = os.path.join(BIN, "servodesk-cli")
SIM = os.path.join(BIN, "servodesk-sim")
passed = failed = 0


def cli(*args, cwd=None):
    return subprocess.run([CLI, *args], capture_output=True, text=True, timeout=60, cwd=cwd)


def check(name, condition, detail=""):
    global passed, failed
    if condition:
        passed += 1
    else:
        failed += 1
        print(f"FAIL {name}: {detail}")


with tempfile.TemporaryDirectory() as tmp:
    hello = os.path.join(tmp, "HELLO.BDS")
    with open(hello, "w") as f:
        f.write('10$\nP "HELLO WORLD"\nB\n')
    bad = os.path.join(tmp, "BAD.BDS")
    with open(bad, "w") as f:
        f.write("1$\nPROP 2\nFOO\nB\n")

    r = cli("send", 'P "HELLO"', "X1=41", "P X1+1")
    check("send", r.returncode == 0 and r.stdout == "HELLO\n          42\n", r)

    r = cli("send", "P 1/0")
    check("send drive error", r.returncode == 1 and "ERR 92" in r.stdout and "ZERO DIVIDE" in r.stderr, r)

    r = cli("check", hello)
    check("check clean", r.returncode == 0 and r.stdout == "", r)
    r = cli("check", bad)
    check("check diagnostics", r.returncode == 1 and r.stdout.splitlines() == [
        f"{bad}:2:6: error: ERR 83 '2' BAD OR OUT OF RANGE", f"{bad}:3:1: error: ERR 80 'FOO' INVALID INSTRUCTION"], r)

    up = os.path.join(tmp, "UP.BDS")
    r = cli("download", hello, "run", "10", "--follow", "2", "upload", up)
    check("download run upload", r.returncode == 0 and "Verified" in r.stdout and "HELLO WORLD\n" in r.stdout, r)
    check("upload text", open(up).read() == open(hello).read(), open(up).read() if os.path.exists(up) else "")

    var = os.path.join(tmp, "SET.VAR")
    r = cli("send", "X7=77", "vars", "dump", var)
    text = open(var).read() if os.path.exists(var) else ""
    check("vars dump", r.returncode == 0 and "\nX7 77\n" in text and "VMAX" not in text.replace(";VMAX", ""), r)
    with open(var, "w") as f:
        f.write(text.replace("X7 77", "X7 78"))
    r = cli("vars", "send", var, "send", "P X7")
    check("vars send", r.returncode == 0 and r.stdout.endswith("          78\n"), r)
    r = cli("send", "EN", "vars", "dump", var)
    check("vars dump enabled", r.returncode == 1 and "ERR 51" in r.stderr + r.stdout, r)

    csv = os.path.join(tmp, "REC.CSV")
    r = cli("send", "PLIM OFF", "EN", "record", "--vars", "VCMD,PCMD", "--count", "100", "--interval", "2",
            "--then", "J 1000", "--csv", csv)
    rows = open(csv).read().splitlines() if os.path.exists(csv) else []
    check("record", r.returncode == 0 and rows[1] == "time_s,VCMD [VEL],PCMD [POS]" and len(rows) == 102
          and rows[-1].split(",")[1] == "1000", (r, rows[:3], rows[-2:]))

    r = cli("stop")
    check("stop", r.returncode == 0, r)
    r = cli("frobnicate")
    check("usage", r.returncode == 2 and "usage:" in r.stderr, r)
    r = cli("--drive", "sc750", "send", "P 1")
    check("unsupported family", r.returncode == 2 and "not supported yet" in r.stderr, r)
    r = cli("--port", "/dev/pts/does-not-exist", "send", "P 1")
    check("no port", r.returncode == 3 and r.stderr.count("\n") == 1, r)

    sim = subprocess.Popen([SIM, "--drive", "bds5", "--pty"], stdout=subprocess.PIPE, text=True)
    try:
        pty = sim.stdout.readline().split()[1]
        r = cli("--port", pty, "send", 'P "OVER THE PTY"', "download", hello, "run", "10", "--follow", "3")
        check("pty", r.returncode == 0 and r.stdout.startswith("OVER THE PTY\n") and "HELLO WORLD" in r.stdout, r)
    finally:
        sim.terminate()
        sim.wait(5)

print(f"servodesk-cli: {passed} passed, {failed} failed")
sys.exit(1 if failed else 0)

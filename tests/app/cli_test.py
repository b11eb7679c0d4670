#!/usr/bin/python3
"""servodesk-cli against the simulated drive (--sim) and through a real pty (servodesk-sim --pty): every
command, the failure paths and the exit codes. Usage: cli_test.py BIN_DIR"""
import os
import subprocess
import sys
import tempfile
import zlib

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
    r = cli("--drive", "sc900", "send", "P 1")
    check("unknown family", r.returncode == 2 and "unknown drive" in r.stderr, r)
    r = cli("compile", hello)
    check("compile is the SC750's", r.returncode == 2 and "only the SC750" in r.stderr, r)

    # The SC750 (issue 17): the same verbs. A ServoBASIC program from the manual's own examples, compiled by
    # the drive's compiler, downloaded (the drive checks the .BIN's CRC-32), run and uploaded back.
    bas = os.path.join(tmp, "COUNT.BAS")
    with open(bas, "w") as f:
        f.write('DIM I AS INTEGER\nFOR I = 1 TO 3\n  PRINT "COUNT "; I\nNEXT I\nEND\n')
    bad_bas = os.path.join(tmp, "BAD.BAS")
    with open(bad_bas, "w") as f:
        f.write("DIM I AS INTEGER\nGOTO NOWHERE\nEND\n")
    r = cli("--drive", "sc750", "check", bas)
    check("sc750 check clean", r.returncode == 0 and r.stdout == "", r)
    r = cli("--drive", "sc750", "check", bad_bas)
    check("sc750 check error", r.returncode == 1 and r.stdout.startswith(f"{bad_bas}:2:") and "NOWHERE" in r.stdout, r)
    binary = os.path.join(tmp, "OUT.BIN")
    r = cli("--drive", "sc750", "compile", bas, "-o", binary)
    check("sc750 compile", r.returncode == 0 and os.path.exists(binary) and open(binary, "rb").read(4) != b"", r)
    up_bas = os.path.join(tmp, "UP.BAS")
    r = cli("--drive", "sc750", "download", bas, "run", "--follow", "3", "upload", up_bas)
    # The CRC the drive checked, against Python's zlib.crc32 (CRC-32/ISO-HDLC, the .BIN's CRC) of the same .BIN.
    check("sc750 download run upload", r.returncode == 0
          and "CRC-32 %08X of the %d-byte .BIN" % (zlib.crc32(open(binary, "rb").read()), os.path.getsize(binary))
          in r.stdout and "COUNT  1 \nCOUNT  2 \nCOUNT  3 \n" in r.stdout, r)
    check("sc750 upload text", os.path.exists(up_bas) and open(up_bas).read() == open(bas).read(),
          open(up_bas).read() if os.path.exists(up_bas) else "")
    r = cli("--drive", "sc750", "send", "KVP=200", "KVP")
    check("sc750 send", r.returncode == 0 and r.stdout == "200\n200\n", r)
    r = cli("--drive", "sc750", "send", "NO.SUCH.THING")
    check("sc750 send error", r.returncode == 1 and "!13" in r.stderr, r)
    r = cli("--drive", "sc750", "download", bad_bas)
    check("sc750 download compile error", r.returncode == 1 and "old program" in r.stderr, r)

    # The PMC-960: MPL at its prompt, a routine downloaded (verified by the communications checksum), run by
    # its label, and its refusal when the servo is not enabled (#B6).
    mpl = os.path.join(tmp, "MOVE.MPL")
    with open(mpl, "w") as f:
        f.write("@T\nSM2\nV10\nI4000+\nD100\nG!\n")
    r = cli("--drive", "pmc960", "check", mpl)
    check("pmc960 check clean", r.returncode == 0 and r.stdout == "", r)
    bad_mpl = os.path.join(tmp, "BAD.MPL")
    with open(bad_mpl, "w") as f:
        f.write("@T\nBZ\n")
    r = cli("--drive", "pmc960", "check", bad_mpl)
    check("pmc960 check label", r.returncode == 1 and r.stdout.startswith(f"{bad_mpl}:2:") and "#C2" in r.stdout, r)
    r = cli("--drive", "pmc960", "send", "A3500", "A?")
    check("pmc960 send", r.returncode == 0 and r.stdout == "3500\n", r)
    r = cli("--drive", "pmc960", "send", "Y")
    check("pmc960 send error", r.returncode == 1 and "#" in r.stderr, r)
    up_mpl = os.path.join(tmp, "UP.MPL")
    r = cli("--drive", "pmc960", "download", mpl, "run", "T", "--follow", "5", "upload", up_mpl)
    check("pmc960 download run upload", r.returncode == 0 and "communications checksum" in r.stdout
          and int(r.stdout.splitlines()[1]) > 0, r)
    check("pmc960 upload text", os.path.exists(up_mpl) and open(up_mpl).read() == open(mpl).read(),
          open(up_mpl).read() if os.path.exists(up_mpl) else "")
    idle = os.path.join(tmp, "IDLE.MPL")
    with open(idle, "w") as f:
        f.write("@T\nI4000+\n")
    r = cli("--drive", "pmc960", "download", idle, "run", "T", "--follow", "5")
    check("pmc960 run refused", r.returncode == 1 and "#B6" in r.stderr and "SM2" in r.stderr, r)
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

    for family, program, run_args, expect in (("sc750", bas, ["run", "--follow", "3"], "COUNT  3"),
                                              ("pmc960", mpl, ["run", "T", "--follow", "5"], "checksum")):
        sim = subprocess.Popen([SIM, "--drive", family, "--pty"], stdout=subprocess.PIPE, text=True)
        try:
            pty = sim.stdout.readline().split()[1]
            r = cli("--drive", family, "--port", pty, "download", program, *run_args)
            check(f"{family} pty", r.returncode == 0 and expect in r.stdout, r)
        finally:
            sim.terminate()
            sim.wait(5)

print(f"servodesk-cli: {passed} passed, {failed} failed")
sys.exit(1 if failed else 0)

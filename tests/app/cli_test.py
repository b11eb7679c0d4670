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
    return subprocess.run([CLI, *args], capture_output=True, text=True, timeout=120, cwd=cwd, env=CLI_ENV)


# A simulator process behind a pty runs in real time and a loaded machine (issue 23: ctest -j 4 beside CPU hogs
# and a build) can leave it unscheduled for seconds: the CLI's time-outs on such a port, meant for a real drive
# that answers in milliseconds, are stretched for the tests (drive_timeout.cpp).
CLI_ENV = dict(os.environ, SERVODESK_TIMEOUT_SCALE="20")


def check(name, condition, detail=""):
    global passed, failed
    if condition:
        passed += 1
    else:
        failed += 1
        print(f"FAIL {name}: {detail}")


def read(path):
    return open(path).read() if os.path.exists(path) else ""


def params(text):
    """NAME -> value of a .PRM's "NAME = value" lines."""
    return {n.strip(): v.strip() for n, v in (line.split("=", 1) for line in text.splitlines() if "=" in line)}


def check_watch(name, r, csv, header, every_ms, for_s, last=None):
    """watch wrote the scope's CSV: the asked columns; at most one row per --every within --for (polls go out
    only while the time lasts, one at a time) and at least two; times from the first poll, increasing; and
    (last) what the final row must show. No lower bound tied to the wall clock: the suite runs under load
    (packaging/flake-hunt.sh), where a poll may wait long for its answer."""
    rows = [line.split(",") for line in read(csv).splitlines()]
    body = rows[1:]
    times = [float(row[0]) for row in body]
    check(name, r.returncode == 0 and rows and rows[0] == header and 2 <= len(body) <= int(for_s * 1000 / every_ms)
          and all(len(row) == len(header) for row in body) and times[0] >= 0
          and all(a < b for a, b in zip(times, times[1:])) and f"{len(body)} samples" in r.stdout
          and (last is None or last(body[-1], body)), (r, rows[:2], rows[-2:], len(body)))


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
    # The scope's own .CSV layout (scope/capture_csv.h), the one Scope > Open reads: RECORD line, titles, rows.
    check("record", r.returncode == 0 and rows[:2] == ["RECORD,100,2,VCMD,PCMD", "Time (s),VCMD (VEL),PCMD (POS)"]
          and len(rows) == 102 and rows[-1].split(",")[1] == "1000", (r, rows[:3], rows[-2:]))

    # watch: polled, each row stamped when it was read. J 1000 jogs at 1000 (VEL); PFB counts up meanwhile.
    watch = os.path.join(tmp, "WATCH.CSV")
    r = cli("send", "PLIM OFF", "EN", "J 1000", "watch", "--vars", "VFB,PFB", "--every", "100", "--for", "2",
            "--csv", watch)
    check_watch("bds5 watch", r, watch, ["Time (s)", "VFB (VEL)", "PFB (POS)"], 100, 2,
                lambda row, rows: row[1] == "1000" and int(row[2]) > int(rows[0][2]))
    r = cli("watch", "--vars", "VFB,NOSUCH", "--every", "100", "--for", "1", "--csv", watch)
    check("bds5 watch unknown", r.returncode == 2 and '"NOSUCH"' in r.stderr
          and "VCMD, VFB, ICMD, PCMD, PFB" in r.stderr, r)
    r = cli("watch", "--vars", "VFB,PFB,VCMD,PCMD,ICMD", "--every", "100", "--for", "1", "--csv", watch)
    check("watch usage", r.returncode == 2 and "1 to 4" in r.stderr, r)

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

    # The SC750's parameter set (.PRM): its PARAMS block, read with G frames. The values a fresh drive holds are
    # the manual's boiler-plate (L946-L973); SIX.THRESH comes back with the 7 digits PRINT shows.
    prm = os.path.join(tmp, "SET.PRM")
    r = cli("--drive", "sc750", "vars", "dump", prm)
    text = read(prm)
    values = params(text)
    manual = {"POLECOUNT": "4", "ILC": "13", "KVP": "0.087086", "KVI": "5.000000", "ARF0": "150.000000",
              "KPP": "15.000000", "BLKTYPE": "2", "ILMT.PLUS": "100", "DACMAP": "1", "ITF0": "0.020000",
              "IT.THRESH": "60", "ADF0": "1000.000000"}
    check("sc750 vars dump", r.returncode == 0 and text.startswith("' ") and "\nPARAMS START\n" in text
          and text.endswith("\nPARAMS END\n") and all(values.get(k) == v for k, v in manual.items())
          and abs(float(values.get("SIX.THRESH", "0")) - 430.664063) < 1e-3, (r, text))
    # Controller Set Up's Auto values for another motor (L2509-L2512): ILC = 59, KVP = 0.062053.
    with open(prm, "w") as f:
        f.write(text.replace("ILC = 13", "ILC = 59").replace("KVP = 0.087086", "KVP = 0.062053"))
    again = os.path.join(tmp, "AGAIN.PRM")
    r = cli("--drive", "sc750", "vars", "send", prm, "vars", "dump", again)
    after = params(read(again))
    check("sc750 vars send", r.returncode == 0 and f"Sent {len(values)} parameter line(s)." in r.stdout
          and after.get("ILC") == "59" and after.get("KVP") == "0.062053" and after.get("KPP") == "15.000000",
          (r, after))
    bad_prm = os.path.join(tmp, "BAD.PRM")
    with open(bad_prm, "w") as f:
        f.write("' KVP above its range, and a line that is no assignment\nPARAMS START\nKVP = 5000\nKVI = 4.5\n"
                "KPP = fast\nPARAMS END\n")
    r = cli("--drive", "sc750", "vars", "send", bad_prm)
    check("sc750 vars send refused", r.returncode == 1 and r.stdout.splitlines() == [
        f"{bad_prm}:3: !14 VALUE OUT OF RANGE FOR KVP 'KVP=5000'",
        f"{bad_prm}:5: not an assignment (NAME = number) 'KPP = fast'"] and r.stderr == "servodesk-cli: Sent 2 "
          "parameter line(s); the drive refused 1 of them; 1 line(s) of the file were not sent.\n", r)

    # watch on the SC750: G frames. GO.VEL at RUN.SPEED 100 RPM; POSITION counts up meanwhile.
    r = cli("--drive", "sc750", "send", "ENABLE=1", "RUN.SPEED=100", "GO.VEL", "watch", "--vars", "VELOCITY,POSITION",
            "--every", "100", "--for", "2", "--csv", watch)
    check_watch("sc750 watch", r, watch, ["Time (s)", "VELOCITY (RPM)", "POSITION (counts)"], 100, 2,
                lambda row, rows: float(row[1]) == 100 and int(row[2]) > int(rows[0][2]))
    r = cli("--drive", "sc750", "watch", "--vars", "POSITON", "--every", "100", "--for", "1", "--csv", watch)
    check("sc750 watch unknown", r.returncode == 2 and '"POSITON"' in r.stderr and "POSITION, POS.ERROR" in r.stderr, r)
    r = cli("--drive", "sc750", "record", "--vars", "POSITION", "--count", "10", "--interval", "1", "--csv", watch)
    check("sc750 record is the BDS5's", r.returncode == 2 and "watch" in r.stderr, r)

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

    # The PMC-960's parameter table as the MPL lines that set it, SW1 ... SW0. The gains of a fresh controller are
    # the manual's defaults (5.7 Tuning Parameters: position, velocity, tach, feedforward 16/16/160/16).
    table = os.path.join(tmp, "TABLE.MPL")
    r = cli("--drive", "pmc960", "vars", "dump", table)
    lines = [line for line in read(table).splitlines() if not line.startswith("@.")]
    check("pmc960 vars dump", r.returncode == 0 and lines[:5] == ["SW1", "TGP16", "TGV16", "TGT160", "TGF16"]
          and lines[-1] == "SW0" and "THA4096" in lines and not any(line.startswith("THB") for line in lines),
          (r, read(table)))
    # The manual's TG examples (L1769-L1773): TGP17, TGV34.
    text = read(table)
    with open(table, "w") as f:
        f.write(text.replace("TGP16\n", "TGP17\n").replace("TGV16\n", "TGV34\n"))
    again = os.path.join(tmp, "AGAIN.MPL")
    r = cli("--drive", "pmc960", "vars", "send", table, "vars", "dump", again, "send", "TGP?", "TGV?")
    lines = read(again).splitlines()
    check("pmc960 vars send", r.returncode == 0 and "TGP17" in lines and "TGV34" in lines and "TGT160" in lines
          and r.stdout.endswith("P-17\nV-34\n"), (r, lines))
    bad_table = os.path.join(tmp, "BAD.MPL")
    with open(bad_table, "w") as f:
        f.write("@.gains_before_write_enable\nTGP20\nSW1\nTGV300\nTGT150\nSW0\n")
    r = cli("--drive", "pmc960", "vars", "send", bad_table)
    check("pmc960 vars send refused", r.returncode == 1 and r.stdout.splitlines() == [
        f"{bad_table}:2: #D3 Write protected 'TGP20'", f"{bad_table}:4: TGV must lie within 0 \u2013 255. 'TGV300'"]
          and "refused 1" in r.stderr, r)

    # watch on the PMC-960: its status polls. J10 jogs at 10 (100 Hz units); position counts up meanwhile.
    r = cli("--drive", "pmc960", "send", "SM2", "J10", "J+", "watch", "--vars", "G,SF,V,I", "--every", "100",
            "--for", "2", "--csv", watch)
    check_watch("pmc960 watch", r, watch, ["Time (s)", "G (counts)", "SF (counts)", "V (V units)", "I (counts)"],
                100, 2, lambda row, rows: row[3] == "10" and int(row[1]) > int(rows[0][1]))
    r = cli("--port", "/dev/pts/does-not-exist", "send", "P 1")
    check("no port", r.returncode == 3 and r.stderr.count("\n") == 1, r)

    sim = subprocess.Popen([SIM, "--drive", "bds5", "--pty"], stdout=subprocess.PIPE, text=True)
    try:
        pty = sim.stdout.readline().split()[1]
        # Six seconds of watch for at least two answers: the simulator process may not run for seconds.
        r = cli("--port", pty, "watch", "--vars", "VFB,PFB", "--every", "100", "--for", "6", "--csv", watch)
        check_watch("pty watch", r, watch, ["Time (s)", "VFB (VEL)", "PFB (POS)"], 100, 6)
        # --follow is drive time, which on a pty is the wall's; HELLO.BDS ends at once, so the bound costs
        # nothing and only a loaded machine (issue 23: ctest -j 4 beside CPU hogs) needs it this long.
        r = cli("--port", pty, "send", 'P "OVER THE PTY"', "download", hello, "run", "10", "--follow", "30")
        check("pty", r.returncode == 0 and r.stdout.startswith("OVER THE PTY\n") and "HELLO WORLD" in r.stdout, r)
    finally:
        sim.terminate()
        sim.wait(60)

    for family, program, run_args, expect, watched in (
            ("sc750", bas, ["run", "--follow", "3"], "COUNT  3", ["POSITION", "VELOCITY"]),
            ("pmc960", mpl, ["run", "T", "--follow", "5"], "checksum", ["G", "SF"])):
        sim = subprocess.Popen([SIM, "--drive", family, "--pty"], stdout=subprocess.PIPE, text=True)
        try:
            pty = sim.stdout.readline().split()[1]
            r = cli("--drive", family, "--port", pty, "watch", "--vars", ",".join(watched), "--every", "100", "--for",
                    "6", "--csv", watch)
            check_watch(f"{family} pty watch", r, watch, ["Time (s)"] + [
                f"{n} ({'RPM' if n == 'VELOCITY' else 'counts'})" for n in watched], 100, 6)
            r = cli("--drive", family, "--port", pty, "download", program, *run_args)
            check(f"{family} pty", r.returncode == 0 and expect in r.stdout, r)
        finally:
            sim.terminate()
            sim.wait(60)

print(f"servodesk-cli: {passed} passed, {failed} failed")
sys.exit(1 if failed else 0)

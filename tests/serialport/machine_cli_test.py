#!/usr/bin/python3
"""servodesk-cli machine backup | compare | restore (issue 21), as a script would use them, against each
family's simulated multidrop line on a pty: a program on the first axis, a backup of every axis, then one
variable changed on another axis and one program line changed on the first; compare lists exactly those two
differences and exits 1, restore puts the backup back and reports each axis, and compare is clean again."""
import os
import subprocess
import sys
import tempfile

from sim_client import simulator

FAMILIES = [
    # family, axes, backup's --ids ([] = the BDS5's scan), program, its changed line, a change on the second axis
    ("bds5", ["A", "B", "C", "D"], [], '10$\nP "HELLO WORLD"\nB\n', (2, 'P "HELLO THERE"'), ["X1=5"], "X1", 5.0),
    ("sc750", ["1", "2", "3"], ["--ids", "1,2,3"],
     'DIM I AS INTEGER\nFOR I = 1 TO 3\n  PRINT "COUNT "; I\nNEXT I\nEND\n', (3, '  PRINT "TALLY "; I'),
     ["KVP=0.05"], "KVP", 0.05),
    ("pmc960", ["A", "B"], ["--ids", "A,B"], "@T\nSM2\nV10\nI4000+\nD100\nG!\n", (3, "V20"),
     ["SW1", "TGP20", "SW0"], "TGP", 20.0),
]


def main(bin_dir):
    cli = os.path.join(bin_dir, "servodesk-cli")
    sim = os.path.join(bin_dir, "servodesk-sim")
    failures = 0

    def run(*args):
        return subprocess.run([cli, *args], capture_output=True, text=True, timeout=600)

    def check(name, ok, r):
        nonlocal failures
        print(("PASS " if ok else "FAIL ") + name)
        if not ok:
            failures += 1
            print(f"  exit {r.returncode}\n  stdout: {r.stdout!r}\n  stderr: {r.stderr!r}")
        return ok

    for family, axes, ids, program, (line_no, new_line), change, name, value in FAMILIES:
        tmp = tempfile.mkdtemp()
        backup = os.path.join(tmp, "backup")
        first, second = axes[0], axes[1]
        prog = os.path.join(tmp, "first." + {"bds5": "bds", "sc750": "bas", "pmc960": "mpl"}[family])
        with open(prog, "w") as f:
            f.write(program)
        with simulator(sim, "--drive", family, "--axes", ",".join(axes), "--pty", "--speed", "10") as line:
            assert line.startswith("PTY /dev/"), line
            port = line[4:]
            on = ["--drive", family, "--port", port]
            # scan: one line per axis that answers, ID first; an ID no axis has is not listed.
            absent = {"bds5": "Z", "sc750": "200", "pmc960": "Z"}[family]
            title = {"bds5": "BDS5", "sc750": "SC750", "pmc960": "PMC-960"}[family]
            r = run(*on, "machine", "scan", "--ids", ",".join(axes + [absent]), "--wait", "500")
            check(f"{family}: scan finds each axis and no other", r.returncode == 0
                  and [l.split()[:2] for l in r.stdout.splitlines()] == [[a, title] for a in axes], r)

            r = run(*on, "--axis", first, "download", prog)
            check(f"{family}: download to axis {first}", r.returncode == 0, r)

            r = run(*on, "machine", "backup", backup, *ids)
            done = [l.split()[0] for l in r.stdout.splitlines() if l.split()[1:2] == ["done"]]
            check(f"{family}: backup of every axis", r.returncode == 0 and done == axes, r)
            project = open(os.path.join(backup, "machine.sdm")).read()
            check(f"{family}: machine.sdm names each axis and its files",
                  all(f"axis {a} {family} axis-{a}." in project for a in axes) and f"port {port} 9600" in project, r)
            kept = open(os.path.join(backup, [l.split()[3] for l in project.splitlines()
                                              if l.startswith(f"axis {first} ")][0])).read().splitlines()
            check(f"{family}: the backup holds axis {first}'s program", kept == program.splitlines(), r)

            r = run(*on, "machine", "compare", backup)
            check(f"{family}: compare right after the backup is clean", r.returncode == 0, r)

            # One variable on the second axis, one program line on the first.
            r = run(*on, "--axis", second, "send", *change)
            check(f"{family}: change a variable on axis {second}", r.returncode == 0, r)
            changed = program.splitlines()
            old_line = changed[line_no - 1]
            changed[line_no - 1] = new_line
            with open(prog, "w") as f:
                f.write("\n".join(changed) + "\n")
            r = run(*on, "--axis", first, "download", prog)
            check(f"{family}: change a program line on axis {first}", r.returncode == 0, r)

            r = run("machine", "compare", backup)  # the project's own port and family
            diffs = [l for l in r.stdout.splitlines() if " variable " in l or " program " in l]
            var = [l for l in diffs if l.startswith(f"{second} variable {name}: file ")]
            var_ok = len(var) == 1 and float(var[0].rsplit(" ", 1)[1]) == value
            prog_ok = f'{first} program line {line_no}: file "{old_line}", drive "{new_line}"' in diffs
            check(f"{family}: compare lists exactly the two differences", r.returncode == 1 and len(diffs) == 2
                  and var_ok and prog_ok and f"{second} differs" in r.stdout and f"{first} differs" in r.stdout, r)

            r = run("machine", "restore", backup)
            restored = [l.split()[0] for l in r.stdout.splitlines() if l.split()[1:2] == ["done"]]
            check(f"{family}: restore sends and checks every axis", r.returncode == 0 and restored == axes
                  and r.stdout.count("(the drive holds ") == len(axes), r)

            r = run("machine", "compare", backup)
            check(f"{family}: compare after the restore is clean", r.returncode == 0
                  and r.stdout.count(" done the drive matches the files") == len(axes), r)

    # Usage: a project naming an axis twice is refused with its line, and nothing is sent.
    tmp = tempfile.mkdtemp()
    with open(os.path.join(tmp, "machine.sdm"), "w") as f:
        f.write("port /dev/null 9600\naxis A bds5 a.bds a.var\naxis A bds5 b.bds b.var\n")
    r = run("machine", "compare", tmp)
    check("a malformed project is refused with its line", r.returncode == 2 and "machine.sdm:3:" in r.stderr
          and "axis A is named twice" in r.stderr, r)

    print(f"{failures} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))

#!/usr/bin/env python3
# Writes the hand-made seed sessions of the BDS5 fuzzer (corpus/bds5/seed-*) in its input format (see
# bds5_drive_fuzz.cpp): text is typed, 0xF8-0xFF bytes are operations. Rerun after changing a seed.
import os

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "corpus", "bds5")

ESC, CTRL_X, CTRL_V = b"\x1b", b"\x18", b"\x16"


def ms(n):  # one step() of n ms (1..256)
    return bytes([0xF8, n - 1])


def tens(n):  # n steps of 10 ms (1..256)
    return bytes([0xF9, n - 1])


def pin(number, on):
    return bytes([0xFA, (number - 1) | (0x80 if on else 0)])


def fault(code):
    return bytes([0xFB, code])


POWER_UP = b"\xfc"


def flood(times16):  # the bytes typed since the last operation, times16*16 times over
    return bytes([0xFD, times16 - 1])


def micro(n):
    return bytes([0xFE, n])


def lit(b):
    return bytes([0xFF, b])


def typed(line, wait=5):  # a line and its CR, then time for the answer
    return line.encode() + b"\r" + ms(wait)


def download(lines):
    out = typed(">BDS")
    for l in lines:
        out += typed(l, 3)
    return out + ESC + ms(3)


SEEDS = {
    "hello": typed('P "HELLO"') + typed("X1=5") + typed("P X1") + typed("P X1[H] X1[5.2] X1[B] X1[C] X1[S]")
    + typed("X2 = X1*3-(X1/2)") + typed("P X2[3] X2[12.3.1] \"^G^M^J\"") + typed("ERR HIST") + typed("ERR 83")
    + typed("ERR CLR") + typed("CLEARX") + typed("EN") + typed("DIS"),
    "errors": typed('P "UNTERMINATED') + typed('P"BAD"') + typed("X1=1/0") + typed("X1=2147483647+1")
    + typed("X1=((((1))))") + typed("X(0)=1") + typed("X(251)=1") + typed("NOSUCH") + typed("GOTO 3")
    + typed("VMAX=-1") + typed("A B C D E F G H I J K L M N O P Q") + typed("X1=0FFFFFFFFH") + typed("? 1 EQ 1"),
    "program-run": download(["1$", "X1=X1+1", "P \"X1 IS \" X1", "D 100", "GOTO 1"]) + typed("<BDS", 50)
    + typed("RUN 1", 50) + tens(30) + ESC + ms(20) + typed("P X1", 20) + typed("S", 20) + typed("RUN 1", 20)
    + ESC + ms(10) + ESC + tens(10) + CTRL_X + ms(5) + typed("P CHECKSUM"),
    "program-control": download(["1$", "X1=0", "2$", "X1=X1+1", "IF X1 LT 3", "GOSUB 5", "ELIF X1 EQ 3",
                                 "P \"THREE\"", "ELSE", "P \"MORE\"", "ENDIF", "TIL X1 GE 5 X1=X1+1",
                                 "? X1 GT 4 P \"BIG\" : P \"SMALL\"", "END", "5$", "GOSUB 6", "RET", "6$",
                                 "GOSUB 7", "RET", "7$", "GOSUB 8", "RET", "8$", "GOSUB 9", "RET", "9$", "GOSUB 9",
                                 "RET"]) + typed("RUN 1", 10) + tens(50) + typed("RUN 2", 10) + tens(50),
    "multitasking": download(["BACKGROUND$", "P \"BG\"", "D 50", "END", "A$ I1 ON", "P \"ALARM\"", "END",
                              "VARIABLE$", "P \"VAR \" X1", "END", "10$", "X1=X1+1", "H I2 ON", "D 20",
                              "GOTO 10"]) + typed("RUN 10", 20) + pin(1, True) + tens(10) + pin(2, True)
    + tens(10) + CTRL_V + tens(10) + pin(1, False) + pin(1, True) + tens(5) + ESC + tens(5) + typed("MULTI=0")
    + ESC + tens(10) + CTRL_X + ms(5) + typed("RUN", 10) + tens(20) + CTRL_X + ms(5),
    "power-up-label": download(["POWER-UP$", "P \"STARTING\"", "TMR1=100", "TIL TMR1 EQ 0", "P \"DONE\"", "B"])
    + POWER_UP + tens(20) + typed("BAUD=19200") + POWER_UP + tens(20) + typed("BAUD=300") + POWER_UP + tens(30),
    "editor": download(["; TEST PROGRAM", "1$", "P \"ONE\"", "B"]) + typed("ED") + typed("P BEG END", 20)
    + typed("P 2") + typed("") + typed("") + typed("") + typed("I 2") + typed("X1=1") + typed("X2=2") + typed("")
    + typed("F") + typed("ONE") + typed("C") + typed("ONE") + typed("TWO") + typed("C") + typed("") + typed("")
    + typed("SIZE") + typed("DEL 2 3") + typed("PASS") + typed("ABC") + typed("I") + typed("PASS") + typed("XYZ")
    + typed("PASS") + typed("ABC") + typed("") + typed("F") + ESC + ms(3) + typed("P 99") + typed("NEW")
    + typed("P") + ESC + ms(5) + typed(">BDS XYZ") + typed("<BDS"),
    "control-characters": b"X1=1" + ESC + ms(2) + b"P X1" + CTRL_X + b"\r" + ms(2) + b"ABC\b\b\x7f\r" + ms(3)
    + b"\x00\x00\x00P\x00 X1\r\n" + ms(3) + CTRL_V + b"\x07\x01\x02\x03\x7f\x7f\x7f\x7f\r" + ms(5),
    "bit7": bytes(range(0x80, 0xF8)) + b"\r" + ms(5) + b"P \"\xe9\xfc\"\r" + ms(5) + lit(0xF8) + lit(0xFF)
    + lit(0xFD) + b"\r" + ms(5) + b">BDS\r" + ms(3) + b"P \"\xc0\xc1\"\r" + ms(3) + ESC + ms(3),
    "nul-flood": b"\x00" * 64 + flood(256) + ms(5) + b"\r" + ms(5),
    "long-line": b"P " + b"X" * 200 + b"\r" + ms(200) + b"A" * 100 + flood(16) + tens(20) + b"\r" + ms(5)
    + b"1234567890" * 20 + b"\r" + tens(20),
    "garbage": bytes((i * 37 + 11) & 0xFF for i in range(600) if ((i * 37 + 11) & 0xFF) < 0xF8) + ms(20)
    + b"\r" + tens(5),
    # A program larger than memory: ERR 86 USER PROGRAM FULL on every line past ~16,000 characters.
    "program-full": typed(">BDS") + (b"X1=X1+1 ; " + b"F" * 69 + b"\r") + flood(16) + ms(100) + ESC + tens(50)
    + typed("ED") + typed("SIZE") + typed("I") + typed("X1=1") + ESC + typed("P END") + typed("C") + typed("X1")
    + typed("X1234567") + ESC + ms(5) + typed("ERR HIST", 50),
    "faults": fault(17) + ms(5) + typed("P X1") + fault(18) + fault(19) + b"P X1\r" + ms(20)
    + download(["1$", "D 1000", "GOTO 1"]) + typed("RUN 1") + fault(17) + tens(5) + typed("RUN 1") + ESC + ms(5)
    + fault(17) + ms(5) + typed("P X1") + typed("") + fault(0) + fault(255) + ESC + ms(5),
    "sub-millisecond": typed("TMR1=5") + micro(200) * 20 + typed("P TMR1") + micro(0) * 10 + micro(255) * 10
    + typed("P TMR1"),
    # Programs that print as fast as the line lets them: each print waits for the previous one (L4637).
    "print-loop": download(["1$", "P X1 \" \" X2[H]", "X1=X1+1", "? X1 LT 50 GOTO 1", "2$", "TIL X2 GE 100 X2=X2+1",
                            "ERR 83", "X1=0", "GOTO 1"]) + typed("RUN 1", 50) + tens(200) + ESC + tens(20),
    "monitor": download(["1$", "X1=X1+1", "D 10", "GOTO 1"]) + typed("RUN 1") + ESC + ms(5) + typed("P X1")
    + typed("X2=1") + typed("ED") + typed(">BDS") + typed("RUN 1") + typed("B") + ms(5) + typed("RUN 1") + ESC
    + ms(5) + typed("K") + typed("RUN 1") + ESC + ms(5) + typed("S"),
}


# Too slow to fuzz from (every mutant would carry megabytes): replayed by CTest only, from corpus/bds5-long.
LONG = {
    # 10 MB without a CR (issue 3): echo up to 80 characters, then a BEL for every byte; nothing else grows.
    "10mb-without-cr": (b"A" * 64 + flood(256)) * 640 + ms(10) + b"\r" + ms(10) + typed("P \"STILL HERE\""),
    "1mb-of-nul-and-bit7": (bytes([0, 0x80, 0xC1, 0xF7]) * 16 + flood(256)) * 64 + ms(10) + typed("P \"STILL HERE\""),
}

# Reproducers of fixed findings: replayed by CTest from corpus/bds5 (and fuzzed from).
CRASH = {
    # ^V between the lines of a >BDS download: each one re-indexed the whole program (fireVariableTask asks
    # for VARIABLE$), so 24 KB of download took minutes. Fixed: appends extend the index (bds5_program.cpp).
    "ctrl-v-during-download-quadratic": typed(">BDS") + (b"X\r\x16" * 64 + flood(4)) * 4 + ms(10) + ESC + ms(10),
    # Prints inside TIL and ? did not wait for the port (L4637): the UART queue grew without bound.
    "til-print-outruns-line": download(["1$", "TIL X1 EQ 1 P \"TIL PRINTS\""]) + typed("RUN 1") + tens(256)
    + tens(256),
    "quick-if-print-outruns-line": download(["1$", "? 1 EQ 1 P \"QUICK IF PRINTS\"", "GOTO 1"]) + typed("RUN 1")
    + tens(256) + tens(256),
}

# Reproducers of findings in files this fuzzer's owner may not change (open/bds5/README.md): the replay
# test does not run them until they are fixed and moved to corpus/bds5.
OPEN = {
    # BACKGROUND$ as the last line: the task runs off the end at no cost and restarts at once, so every
    # step() spins kMaxLinesPerAdvance (100,000) times (bds5_executor.cpp).
    "background-last-line-spins": download(["BACKGROUND$"]) + typed("RUN") + tens(100),
    # ERR HIST / ERR n print without waiting for the port (L4637): the UART queue grows without bound.
    "err-hist-loop-outruns-line": download(["1$", "ERR HIST", "GOTO 1"]) + typed("RUN 1") + tens(256) + tens(256),
    # ^V between lines typed in the editor's insert mode: each insert invalidates the program index and
    # each ^V re-indexes it all (fireVariableTask looks VARIABLE$ up before checking that multitasking is
    # on), quadratic in the program's length (30 s unoptimised for 24 KB).
    "ctrl-v-in-editor-quadratic": download(["1$"]) + typed("ED") + typed("I 1") + (b"X\r\x16" * 64 + flood(4)) * 4
    + ms(10) + ESC + ms(10),
}


def write(directory, prefix, seeds):
    os.makedirs(directory, exist_ok=True)
    for name, data in seeds.items():
        with open(os.path.join(directory, prefix + name), "wb") as f:
            f.write(data)
    print(f"wrote {len(seeds)} files to {directory}")


def main():
    write(OUT, "seed-", SEEDS)
    write(OUT + "-long", "seed-", LONG)
    write(OUT, "crash-", CRASH)
    write(os.path.join(HERE, "open", "bds5"), "crash-", OPEN)


if __name__ == "__main__":
    main()

#!/usr/bin/python3
# servodesk-sim --drive sc750 --pty answers the SC750 protocol (drive_core/sc750/PROTOCOL.md) on a real
# pseudo-terminal: status, identify, and a variable read, frame bytes exactly as specified.
import os, subprocess, sys, time, tty

sim = sys.argv[1]
p = subprocess.Popen([sim, '--drive', 'sc750', '--pty'], stdout=subprocess.PIPE, text=True)
try:
    line = p.stdout.readline().strip()
    assert line.startswith('PTY '), line
    fd = os.open(line.split()[1], os.O_RDWR | os.O_NOCTTY)
    tty.setraw(fd)

    def frame(letter, payload=''):
        body = letter + payload
        return b'\x01' + body.encode() + ('%02X' % (sum(body.encode()) % 256)).encode() + b'\r'

    def ask(letter, payload=''):
        os.write(fd, frame(letter, payload))
        answer, deadline = b'', time.time() + 5
        while not answer.endswith(b'\r') and time.time() < deadline:
            try:
                answer += os.read(fd, 100)
            except BlockingIOError:
                time.sleep(0.01)
        return answer

    assert ask('?') == b'\x01SN,0,0,0,112\r', ask('?')
    assert ask('V') == frame('V', '752,2.8,1,255')
    assert ask('G', 'RUN.SPEED') == frame('G', 'RUN.SPEED=1000')
    print('sc750 pty: ok')
finally:
    p.terminate()
    p.wait()

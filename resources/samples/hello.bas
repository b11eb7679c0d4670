'----- HELLO.BAS: a first ServoBASIC Plus program for the SC750 -----
' It greets you, turns the motor one revolution three times, printing
' where the motor is after each turn, and says Done.
' To run it: Compile > Run Program (Ctrl+R) compiles it, downloads it to
' the SC750 (the simulated one unless you chose a port) and starts it.
' Its PRINT lines appear in the Output window (F4); Compile > Stop Program
' stops it. A comment starts with ' and runs to the end of the line.

'----- Variable Definitions -----
DIM Turn AS INTEGER

'----- Main Program -----
PRINT "Hello, world"
ENABLE = 1                  ' turn the drive on: no motion without it
PAUSE.TIME = 0.1            ' seconds
PAUSE                       ' give it a moment to come on
IF ENABLED = 0 THEN
    PRINT "The drive is not enabled: check its ENABLE input"
ELSE
    ACCEL.RATE = 10000      ' rpm per second
    DECEL.RATE = 10000
    RUN.SPEED = 500         ' rpm
    INDEX.DIST = 4096       ' one revolution is 4096 counts
    FOR Turn = 1 TO 3
        GO.INCR             ' starts the move; the program goes on at once,
        WHILE MOVING : WEND ' so wait here until the move has ended
        PRINT "Turn"; Turn; "done, position"; POSITION
    NEXT Turn
    PRINT "Done"
END IF
END ' Main Program

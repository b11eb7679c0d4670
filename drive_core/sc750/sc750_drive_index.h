// Catalog indices of the SC750 variables the simulated drive computes or reacts to, looked up once by name.
#pragma once

#include <cstdint>
#include <vector>

namespace drive_core::sc750 {

// What a read of a variable returns: the stored value, or one the drive computes from its state.
enum class Reading : std::uint8_t {
    Stored, PosCmd, Position, PosError, ResPos, Velocity, Rvel, VelCmd, VelErr, Icmd, Ifb, Moving, InPosition,
    AnalogIn, Dacmon, Enabled, FaultCode, Time, AxisAddr, LoggedOn, Inputs, Input, Output, EncPos, GearLock,
    GearError, EncFreq
};

struct DriveIndex {
    int enable, enabled, faultcode, poscmd, position, poserror, respos, velocity, rvel, velcmd, moving, inposition,
        inposlimit, time, axisaddr, loggedon, accel, decel, speed, dir, indexdist, target, pausetime, inputs, outputs,
        pwm12, inp1, out1, intr0, tmenable1, tmout1, whenPcmd, whenPos, whenEncpos, whenRespos, whenRvel, whenTime,
        whenAnalog, whenDacmon, whenIcmd, whenIfb, whenVelcmd, encpos, encfreq, analogin, ratio, dacmap, dmgain,
        blktype, autostart, gearing, gearlock, gearerror, encin, pulsesin, pulsesout, accelgear, decelgear, acceltype,
        regmode, regfunc, regdist, regflag, regpos, regrespos, regencpos, dacmon, adf0, adoffset, dmf0, encout,
        analogout, cwot, ccwot, poserrmoving, poserrstopped, kvp, kvi, kpp, kvff, arf0, arf1, ilc, ilmtplus, ilmtminus,
        cmdgain, itf0, itthresh, model, velerr, icmd, ifb;
    std::vector<Reading> reading; // by catalog index: a read looks here first (programs poll MOVING every tick)
};

const DriveIndex& driveIndex();

} // namespace drive_core::sc750

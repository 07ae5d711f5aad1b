<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en" sourcelanguage="en">
<context>
    <name>AlarmDetailOverlay</name>
    <message>
        <location filename="../../app/screens/alarm_detail.py" line="+128" />
        <source>What was found</source>
        <translation>What was found</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Source: %1</source>
        <translation>Source: %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Kind: %1</source>
        <translation>Kind: %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Device reports: %1</source>
        <translation>Device reports: %1</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Probable causes</source>
        <translation>Probable causes</translation>
    </message>
    <message>
        <location line="+5" />
        <source>What to do</source>
        <translation>What to do</translation>
    </message>
    <message>
        <location line="+3" />
        <source>History</source>
        <translation>History</translation>
    </message>
    <message>
        <location line="+23" />
        <source>Acknowledge</source>
        <translation>Acknowledge</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Close</source>
        <translation>Close</translation>
    </message>
</context>
<context>
    <name>AlarmStates</name>
    <message>
        <location filename="../../app/screens/texts.py" line="+70" />
        <location line="+8" />
        <source>normal</source>
        <translation>normal</translation>
    </message>
    <message>
        <location line="-7" />
        <location line="+8" />
        <source>active, unacknowledged</source>
        <translation>active, unacknowledged</translation>
    </message>
    <message>
        <location line="-7" />
        <location line="+8" />
        <source>active, acknowledged</source>
        <translation>active, acknowledged</translation>
    </message>
    <message>
        <location line="-7" />
        <location line="+8" />
        <source>cleared, unacknowledged</source>
        <translation>cleared, unacknowledged</translation>
    </message>
    <message>
        <location line="+1" />
        <source>shelved</source>
        <translation>shelved</translation>
    </message>
    <message>
        <location line="+10" />
        <source>fault</source>
        <translation>fault</translation>
    </message>
    <message>
        <location line="+1" />
        <source>warning</source>
        <translation>warning</translation>
    </message>
</context>
<context>
    <name>AlarmText</name>
    <message>
        <location filename="catalogue_strings.py" line="+176" />
        <source>A cable to the motor or its encoder is damaged.</source>
        <translation>A cable to the motor or its encoder is damaged.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>A device answered but refused what the machine asked of it.</source>
        <translation>A device answered but refused what the machine asked of it.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>A device was replaced by another model or firmware.</source>
        <translation>A device was replaced by another model or firmware.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>A drive did not switch its power stage on when asked.</source>
        <translation>A drive did not switch its power stage on when asked.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>A drive no longer knows where its axis is; the cut was stopped.</source>
        <translation>A drive no longer knows where its axis is; the cut was stopped.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>A drive or encoder problem.</source>
        <translation>A drive or encoder problem.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>A drive or the I/O module lost its supply or restarted.</source>
        <translation>A drive or the I/O module lost its supply or restarted.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>A drive or the I/O refused a request</source>
        <translation>A drive or the I/O refused a request</translation>
    </message>
    <message>
        <location line="+1" />
        <source>A drive or the I/O reported an event; the machine keeps going.</source>
        <translation>A drive or the I/O reported an event; the machine keeps going.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>A drive switched its power stage off while the axis was meant to move.</source>
        <translation>A drive switched its power stage off while the axis was meant to move.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>A faulty or misadjusted sensor.</source>
        <translation>A faulty or misadjusted sensor.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>A jog stopped because the screen no longer confirmed that its button is held.</source>
        <translation>A jog stopped because the screen no longer confirmed that its button is held.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>A limit switch is faulty or was hit by a board.</source>
        <translation>A limit switch is faulty or was hit by a board.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>A network or bus cable is unplugged or broken.</source>
        <translation>A network or bus cable is unplugged or broken.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>A safety relay or a wire of the chain is open.</source>
        <translation>A safety relay or a wire of the chain is open.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>A servo drive reports a fault and has switched its motor off.</source>
        <translation>A servo drive reports a fault and has switched its motor off.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>A software fault.</source>
        <translation>A software fault.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>A switch between them failed.</source>
        <translation>A switch between them failed.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>A warning inside the device.</source>
        <translation>A warning inside the device.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>A wrong PIN was tried several times.</source>
        <translation>A wrong PIN was tried several times.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Air pressure too low.</source>
        <translation>Air pressure too low.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>An axis did not find its home position within the expected time.</source>
        <translation>An axis did not find its home position within the expected time.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>An axis lags too far behind where it should be; it was stopped before it could go somewhere unexpected.</source>
        <translation>An axis lags too far behind where it should be; it was stopped before it could go somewhere unexpected.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>An axis ran onto its end-of-travel switch and was stopped.</source>
        <translation>An axis ran onto its end-of-travel switch and was stopped.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>An axis stands where the approach cannot go round the board.</source>
        <translation>An axis stands where the approach cannot go round the board.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>An emergency stop button is pressed.</source>
        <translation>An emergency stop button is pressed.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>An encoder signal was lost.</source>
        <translation>An encoder signal was lost.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Another program holds the database.</source>
        <translation>Another program holds the database.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Axis lost its home position</source>
        <translation>Axis lost its home position</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Board removed during the cycle</source>
        <translation>Board removed during the cycle</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Board too narrow to close the barrel</source>
        <translation>Board too narrow to close the barrel</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Call a technician to free disk space or the database; the records are written once it answers.</source>
        <translation>Call a technician to free disk space or the database; the records are written once it answers.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Call a technician with the code in the details; then press Reset.</source>
        <translation>Call a technician with the code in the details; then press Reset.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Centering device did not reach its sensor</source>
        <translation>Centering device did not reach its sensor</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Check the air pressure and the centering device, then press Reset.</source>
        <translation>Check the air pressure and the centering device, then press Reset.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Check the air pressure and the clamps, then press Reset.</source>
        <translation>Check the air pressure and the clamps, then press Reset.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Check the axis and its home switch, then press Reset and home again.</source>
        <translation>Check the axis and its home switch, then press Reset and home again.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Check the cables and the supply of the device named in the details, then press Reset (it reconnects).</source>
        <translation>Check the cables and the supply of the device named in the details, then press Reset (it reconnects).</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Check the cutter and the motor protection. Press Reset, then resume or abandon the board.</source>
        <translation>Check the cutter and the motor protection. Press Reset, then resume or abandon the board.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Check the drive's display and its supply, then press Reset.</source>
        <translation>Check the drive's display and its supply, then press Reset.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Check the emergency stop buttons and the drive's display, then press Reset.</source>
        <translation>Check the emergency stop buttons and the drive's display, then press Reset.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Check the gauge and its cable, then press Reset: the board is measured again.</source>
        <translation>Check the gauge and its cable, then press Reset: the board is measured again.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Check the gauge's display and cable, then press Reset.</source>
        <translation>Check the gauge's display and cable, then press Reset.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Check the handwheel's cable and plug, then press Reset. If it repeats, call a technician.</source>
        <translation>Check the handwheel's cable and plug, then press Reset. If it repeats, call a technician.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Check the spindle's motor protection switch, then press Reset.</source>
        <translation>Check the spindle's motor protection switch, then press Reset.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Clamps did not reach their sensor</source>
        <translation>Clamps did not reach their sensor</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Clear the axis, check that it moves freely, then press Reset. If it repeats, lower the feed or call a technician.</source>
        <translation>Clear the axis, check that it moves freely, then press Reset. If it repeats, lower the feed or call a technician.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Close the guard, check that nothing is in the way, then press Reset.</source>
        <translation>Close the guard, check that nothing is in the way, then press Reset.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Communication with the drives or I/O lost</source>
        <translation>Communication with the drives or I/O lost</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Cut to fit, this board would leave a gap in the barrel that no stave can close.</source>
        <translation>Cut to fit, this board would leave a gap in the barrel that no stave can close.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Device event</source>
        <translation>Device event</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Drive did not enable</source>
        <translation>Drive did not enable</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Drive fault</source>
        <translation>Drive fault</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Drive not enabled during motion</source>
        <translation>Drive not enabled during motion</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Electrical noise on the handwheel's cable or a bad connector.</source>
        <translation>Electrical noise on the handwheel's cable or a bad connector.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Emergency stop</source>
        <translation>Emergency stop</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Feed or acceleration set higher than the axis can follow.</source>
        <translation>Feed or acceleration set higher than the axis can follow.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Following error too large</source>
        <translation>Following error too large</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Guard open during motion</source>
        <translation>Guard open during motion</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Handwheel count jumped further than a hand can turn it</source>
        <translation>Handwheel count jumped further than a hand can turn it</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Homing did not complete</source>
        <translation>Homing did not complete</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Internal error in the machine process</source>
        <translation>Internal error in the machine process</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Jog stopped: no refresh from the screen</source>
        <translation>Jog stopped: no refresh from the screen</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Limit switch reached</source>
        <translation>Limit switch reached</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Make sure nobody is in danger, release the button (turn it), then press Reset.</source>
        <translation>Make sure nobody is in danger, release the button (turn it), then press Reset.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Make sure the table is clear or the board is in place, then press Reset.</source>
        <translation>Make sure the table is clear or the board is in place, then press Reset.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Measured width not allowed for this recipe</source>
        <translation>Measured width not allowed for this recipe</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Move refused: it would cross the board</source>
        <translation>Move refused: it would cross the board</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Note the time and the details, press Reset, and tell service.</source>
        <translation>Note the time and the details, press Reset, and tell service.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Over-current or over-temperature: the axis is stuck or overloaded.</source>
        <translation>Over-current or over-temperature: the axis is stuck or overloaded.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>PIN entry locked after repeated wrong PINs</source>
        <translation>PIN entry locked after repeated wrong PINs</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Plug the gauge in again, then press Reset (it reconnects).</source>
        <translation>Plug the gauge in again, then press Reset (it reconnects).</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Press Reset and home the machine before the next board.</source>
        <translation>Press Reset and home the machine before the next board.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Press Reset, jog the axis away from the switch on the Manual screen (the opposite direction only), then home the machine.</source>
        <translation>Press Reset, jog the axis away from the switch on the Manual screen (the opposite direction only), then home the machine.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Press Reset, move the cutter clear of the board on the Manual screen, then start again.</source>
        <translation>Press Reset, move the cutter clear of the board on the Manual screen, then start again.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Press and hold the jog button again.</source>
        <translation>Press and hold the jog button again.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Production and alarm records are kept on the side because the database is busy or missing; nothing is lost yet.</source>
        <translation>Production and alarm records are kept on the side because the database is busy or missing; nothing is lost yet.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Read the details; call a technician if it repeats.</source>
        <translation>Read the details; call a technician if it repeats.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Read the fault code in the details, look at the axis for anything jammed, then press Reset. If it comes back, call a technician with the code.</source>
        <translation>Read the fault code in the details, look at the axis for anything jammed, then press Reset. If it comes back, call a technician with the code.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Records waiting for the database</source>
        <translation>Records waiting for the database</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Somebody opened the guard.</source>
        <translation>Somebody opened the guard.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Spindle did not start</source>
        <translation>Spindle did not start</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Spindle stopped while cutting</source>
        <translation>Spindle stopped while cutting</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Supply voltage too high or too low.</source>
        <translation>Supply voltage too high or too low.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Take the board off (or choose the right recipe), then press Reset.</source>
        <translation>Take the board off (or choose the right recipe), then press Reset.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Take the board off and check the recipe, then press Reset.</source>
        <translation>Take the board off and check the recipe, then press Reset.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Take the board off and check the recipe, then press Reset. If it repeats with a good recipe, call service with the details.</source>
        <translation>Take the board off and check the recipe, then press Reset. If it repeats with a good recipe, call service with the details.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Take the board off and put a wider one on, then press Reset.</source>
        <translation>Take the board off and put a wider one on, then press Reset.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The axis is blocked or runs stiffly (chips, a board in the way, dry guides).</source>
        <translation>The axis is blocked or runs stiffly (chips, a board in the way, dry guides).</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The axis was blocked or stopped during homing.</source>
        <translation>The axis was blocked or stopped during homing.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The axis was jogged past its range.</source>
        <translation>The axis was jogged past its range.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The board is in the way or the clamps are jammed.</source>
        <translation>The board is in the way or the clamps are jammed.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The board is in the way or the device is jammed.</source>
        <translation>The board is in the way or the device is jammed.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The board is narrower or wider than the recipe can cut; it was not cut.</source>
        <translation>The board is narrower or wider than the recipe can cut; it was not cut.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The board is narrower than the barrel still needs.</source>
        <translation>The board is narrower than the barrel still needs.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The board is too narrow or too wide for this recipe.</source>
        <translation>The board is too narrow or too wide for this recipe.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The board is wider than the machine can cut.</source>
        <translation>The board is wider than the machine can cut.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The board was taken off or moved.</source>
        <translation>The board was taken off or moved.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The centering device did not extend or retract in time.</source>
        <translation>The centering device did not extend or retract in time.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The clamps did not close or open in time, as their sensor reports.</source>
        <translation>The clamps did not close or open in time, as their sensor reports.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The computer no longer hears a drive or the I/O; the machine stopped.</source>
        <translation>The computer no longer hears a drive or the I/O; the machine stopped.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The cut would need an axis beyond its travel; nothing moved there.</source>
        <translation>The cut would need an axis beyond its travel; nothing moved there.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The device is configured differently from the machine's configuration.</source>
        <translation>The device is configured differently from the machine's configuration.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The disk is full or slow.</source>
        <translation>The disk is full or slow.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The drive is in fault or has no supply.</source>
        <translation>The drive is in fault or has no supply.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The drive lost its supply.</source>
        <translation>The drive lost its supply.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The drive was switched off or restarted.</source>
        <translation>The drive was switched off or restarted.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The drive's enable or safe torque off input dropped.</source>
        <translation>The drive's enable or safe torque off input dropped.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The emergency stop chain is open: every drive stopped and lost power.</source>
        <translation>The emergency stop chain is open: every drive stopped and lost power.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The emergency stop chain or safe torque off is still open.</source>
        <translation>The emergency stop chain or safe torque off is still open.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The gauge is not in contact with the board.</source>
        <translation>The gauge is not in contact with the board.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The gauge lost its supply.</source>
        <translation>The gauge lost its supply.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The gauge reports its own error (out of range, no contact).</source>
        <translation>The gauge reports its own error (out of range, no contact).</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The gauge's cable is loose.</source>
        <translation>The gauge's cable is loose.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The gauge's cable or adapter is unplugged.</source>
        <translation>The gauge's cable or adapter is unplugged.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The guard switch is loose or badly adjusted.</source>
        <translation>The guard switch is loose or badly adjusted.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The guard was opened while an axis or the cutter moved; the machine stopped.</source>
        <translation>The guard was opened while an axis or the cutter moved; the machine stopped.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The handwheel or its counter input is faulty.</source>
        <translation>The handwheel or its counter input is faulty.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The handwheel's counter changed by more between two readings than a hand can turn it; nothing moved on that reading.</source>
        <translation>The handwheel's counter changed by more between two readings than a hand can turn it; nothing moved on that reading.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>The home position is lost or wrong.</source>
        <translation>The home position is lost or wrong.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The home switch is faulty, dirty or out of place.</source>
        <translation>The home switch is faulty, dirty or out of place.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The machine could not compute the cut for this board.</source>
        <translation>The machine could not compute the cut for this board.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The machine's software met a situation it does not handle; it stopped safely.</source>
        <translation>The machine's software met a situation it does not handle; it stopped safely.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The motor protection tripped (a blunt cutter, too much feed).</source>
        <translation>The motor protection tripped (a blunt cutter, too much feed).</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The part-present sensor lost the board while the cycle was using it.</source>
        <translation>The part-present sensor lost the board while the cycle was using it.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The recipe's stave does not fit this machine.</source>
        <translation>The recipe's stave does not fit this machine.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The recipe's values give no shape for this width.</source>
        <translation>The recipe's values give no shape for this width.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The screen was busy or frozen.</source>
        <translation>The screen was busy or frozen.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The sensor is dirty or misadjusted.</source>
        <translation>The sensor is dirty or misadjusted.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The spindle did not report running in time; nothing was cut.</source>
        <translation>The spindle did not report running in time; nothing was cut.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The spindle stopped during a cut; the axes were stopped at once.</source>
        <translation>The spindle stopped during a cut; the axes were stopped at once.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The spindle's contactor or its running signal is faulty.</source>
        <translation>The spindle's contactor or its running signal is faulty.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The spindle's motor protection tripped.</source>
        <translation>The spindle's motor protection tripped.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The supply of the spindle dropped.</source>
        <translation>The supply of the spindle dropped.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The touch was lost while holding the button.</source>
        <translation>The touch was lost while holding the button.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The way to the cut would take the cutter through the board; nothing moved.</source>
        <translation>The way to the cut would take the cutter through the board; nothing moved.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The width gauge sent no measurement in time; the board was not cut.</source>
        <translation>The width gauge sent no measurement in time; the board was not cut.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The width gauge sent something that is not a width.</source>
        <translation>The width gauge sent something that is not a width.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The width gauge's connection is gone; no board can be measured.</source>
        <translation>The width gauge's connection is gone; no board can be measured.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The wrong recipe is selected.</source>
        <translation>The wrong recipe is selected.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Too many wrong PINs were entered; PIN entry waits before it accepts another.</source>
        <translation>Too many wrong PINs were entered; PIN entry waits before it accepts another.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Tool path could not be planned</source>
        <translation>Tool path could not be planned</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Tool path outside the axis travel</source>
        <translation>Tool path outside the axis travel</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Wait until the lock ends, then enter the right PIN.</source>
        <translation>Wait until the lock ends, then enter the right PIN.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Width gauge disconnected</source>
        <translation>Width gauge disconnected</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Width gauge gave no reading</source>
        <translation>Width gauge gave no reading</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Width gauge reading not understood</source>
        <translation>Width gauge reading not understood</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Wrong serial settings or a faulty cable.</source>
        <translation>Wrong serial settings or a faulty cable.</translation>
    </message>
</context>
<context>
    <name>AlarmsScreen</name>
    <message>
        <location filename="../../app/screens/alarms_screen.py" line="+170" />
        <source>Alarms</source>
        <translation>Alarms</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Active alarms</source>
        <translation>Active alarms</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Acknowledge all</source>
        <translation>Acknowledge all</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Reset machine</source>
        <translation>Reset machine</translation>
    </message>
    <message>
        <location line="+1" />
        <source>No active alarms.</source>
        <translation>No active alarms.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>History</source>
        <translation>History</translation>
    </message>
    <message>
        <location line="+2" />
        <source>1 hour</source>
        <translation>1 hour</translation>
    </message>
    <message>
        <location line="+1" />
        <source>24 hours</source>
        <translation>24 hours</translation>
    </message>
    <message>
        <location line="+1" />
        <source>7 days</source>
        <translation>7 days</translation>
    </message>
    <message>
        <location line="+1" />
        <source>All</source>
        <translation>All</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Code: %1</source>
        <translation>Code: %1</translation>
    </message>
    <message>
        <location line="+0" />
        <location line="+3" />
        <source>all</source>
        <translation>all</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Source: %1</source>
        <translation>Source: %1</translation>
    </message>
    <message>
        <location line="+4" />
        <location line="+10" />
        <source>Time</source>
        <translation>Time</translation>
    </message>
    <message>
        <location line="-9" />
        <location line="+10" />
        <source>Code</source>
        <translation>Code</translation>
    </message>
    <message>
        <location line="-9" />
        <location line="+10" />
        <source>Alarm</source>
        <translation>Alarm</translation>
    </message>
    <message>
        <location line="-9" />
        <location line="+10" />
        <location line="+124" />
        <source>Source</source>
        <translation>Source</translation>
    </message>
    <message>
        <location line="-133" />
        <source>State</source>
        <translation>State</translation>
    </message>
    <message>
        <location line="+10" />
        <source>New state</source>
        <translation>New state</translation>
    </message>
    <message>
        <location line="+1" />
        <source>User</source>
        <translation>User</translation>
    </message>
    <message>
        <location line="+52" />
        <source>Acknowledge</source>
        <translation>Acknowledge</translation>
    </message>
    <message>
        <location line="+59" />
        <source>All codes</source>
        <translation>All codes</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Alarm code</source>
        <translation>Alarm code</translation>
    </message>
    <message>
        <location line="+5" />
        <source>All sources</source>
        <translation>All sources</translation>
    </message>
</context>
<context>
    <name>BarrelOverlay</name>
    <message>
        <location filename="../../app/screens/barrel_overlay.py" line="+31" />
        <source>Close</source>
        <translation>Close</translation>
    </message>
    <message>
        <location line="+12" />
        <source>Barrel %1</source>
        <translation>Barrel %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Staves: %1</source>
        <translation>Staves: %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Closed</source>
        <translation>Closed</translation>
    </message>
    <message>
        <location line="+2" />
        <source>The next board is stave 1.</source>
        <translation>The next board is stave 1.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Gap %1</source>
        <translation>Gap %1</translation>
    </message>
</context>
<context>
    <name>BarrelPanel</name>
    <message>
        <location filename="../../app/screens/barrel_panel.py" line="+94" />
        <source>Closing stave</source>
        <translation>Closing stave</translation>
    </message>
    <message>
        <location line="+1" />
        <source>One more stave</source>
        <translation>One more stave</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+98" />
        <source>Cooper's card</source>
        <translation>Cooper's card</translation>
    </message>
    <message>
        <location line="-42" />
        <source>No barrel is being raised</source>
        <translation>No barrel is being raised</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Start a barrel</source>
        <translation>Start a barrel</translation>
    </message>
    <message>
        <location line="+2" />
        <source>New barrel</source>
        <translation>New barrel</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Barrel %1</source>
        <translation>Barrel %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Staves: %1</source>
        <translation>Staves: %1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Closed</source>
        <translation>Closed</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The next board starts a new barrel.</source>
        <translation>The next board starts a new barrel.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The next board is stave 1.</source>
        <translation>The next board is stave 1.</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Left %1 · gap %2</source>
        <translation>Left %1 · gap %2</translation>
    </message>
    <message>
        <location line="+5" />
        <source>About %1 more staves</source>
        <translation>About %1 more staves</translation>
    </message>
    <message>
        <location line="+6" />
        <source>A stave of %1 closes it. Next board:</source>
        <translation>A stave of %1 closes it. Next board:</translation>
    </message>
    <message>
        <location line="+23" />
        <source>Card not written: %1</source>
        <translation>Card not written: %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Cooper's card written to %1.</source>
        <translation>Cooper's card written to %1.</translation>
    </message>
</context>
<context>
    <name>ChoiceOverlay</name>
    <message>
        <location filename="../../app/screens/widgets/dialogs.py" line="+125" />
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
</context>
<context>
    <name>ConfirmOverlay</name>
    <message>
        <location line="-65" />
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
</context>
<context>
    <name>FeedOverride</name>
    <message>
        <location filename="../../app/screens/widgets/feed_override.py" line="+71" />
        <source>Feed override</source>
        <translation>Feed override</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Slower by 10 %</source>
        <translation>Slower by 10 %</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Faster by 10 %</source>
        <translation>Faster by 10 %</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The recipe's feed</source>
        <translation>The recipe's feed</translation>
    </message>
</context>
<context>
    <name>FileChooser</name>
    <message>
        <location filename="../../app/screens/widgets/file_chooser.py" line="+85" />
        <source>▲ Up</source>
        <translation>▲ Up</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Home</source>
        <translation>Home</translation>
    </message>
    <message>
        <location line="+20" />
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Save here</source>
        <translation>Save here</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Open</source>
        <translation>Open</translation>
    </message>
    <message>
        <location line="+58" />
        <source>File name</source>
        <translation>File name</translation>
    </message>
    <message>
        <location line="+18" />
        <source>A file name cannot contain '/'.</source>
        <translation>A file name cannot contain '/'.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>The file name must end in %1.</source>
        <translation>The file name must end in %1.</translation>
    </message>
    <message>
        <location line="+1" />
        <source> or </source>
        <translation> or </translation>
    </message>
    <message>
        <location line="+12" />
        <source>Choose a file first.</source>
        <translation>Choose a file first.</translation>
    </message>
</context>
<context>
    <name>IoScreen</name>
    <message>
        <location filename="../../app/screens/io_screen.py" line="+103" />
        <location line="+3" />
        <source>Inputs and outputs</source>
        <translation>Inputs and outputs</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Inputs</source>
        <translation>Inputs</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Outputs</source>
        <translation>Outputs</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Back</source>
        <translation>Back</translation>
    </message>
    <message>
        <location line="+8" />
        <source>not wired</source>
        <translation>not wired</translation>
    </message>
    <message>
        <location line="+2" />
        <source>simulated</source>
        <translation>simulated</translation>
    </message>
    <message>
        <location line="+23" />
        <source>Backend: %1</source>
        <translation>Backend: %1</translation>
    </message>
    <message>
        <location line="+8" />
        <source>ON</source>
        <translation>ON</translation>
    </message>
    <message>
        <location line="+0" />
        <source>off</source>
        <translation>off</translation>
    </message>
</context>
<context>
    <name>IoSignals</name>
    <message>
        <location filename="../../app/screens/io_status.py" line="+26" />
        <source>Spindle</source>
        <translation>Spindle</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Clamps</source>
        <translation>Clamps</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Centering</source>
        <translation>Centering</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Board</source>
        <translation>Board</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Guard</source>
        <translation>Guard</translation>
    </message>
    <message>
        <location line="+1" />
        <source>E-stop chain</source>
        <translation>E-stop chain</translation>
    </message>
    <message>
        <location line="+4" />
        <source>running</source>
        <translation>running</translation>
    </message>
    <message>
        <location line="+1" />
        <source>stopped</source>
        <translation>stopped</translation>
    </message>
    <message>
        <location line="+1" />
        <source>closed</source>
        <translation>closed</translation>
    </message>
    <message>
        <location line="+1" />
        <source>open</source>
        <translation>open</translation>
    </message>
    <message>
        <location line="+1" />
        <source>OPEN</source>
        <translation>OPEN</translation>
    </message>
    <message>
        <location line="+1" />
        <source>moving</source>
        <translation>moving</translation>
    </message>
    <message>
        <location line="+1" />
        <source>extended</source>
        <translation>extended</translation>
    </message>
    <message>
        <location line="+1" />
        <source>retracted</source>
        <translation>retracted</translation>
    </message>
    <message>
        <location line="+1" />
        <source>present</source>
        <translation>present</translation>
    </message>
    <message>
        <location line="+1" />
        <source>none</source>
        <translation>none</translation>
    </message>
    <message>
        <location line="+1" />
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <location line="+1" />
        <source>BROKEN</source>
        <translation>BROKEN</translation>
    </message>
    <message>
        <location line="+63" />
        <source>Board present</source>
        <translation>Board present</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Centering extended</source>
        <translation>Centering extended</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Centering retracted</source>
        <translation>Centering retracted</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Clamps closed</source>
        <translation>Clamps closed</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Clamps open</source>
        <translation>Clamps open</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Spindle running</source>
        <translation>Spindle running</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Guard closed</source>
        <translation>Guard closed</translation>
    </message>
    <message>
        <location line="+1" />
        <source>E-stop chain closed</source>
        <translation>E-stop chain closed</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Start push button</source>
        <translation>Start push button</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Stop push button</source>
        <translation>Stop push button</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Reset push button</source>
        <translation>Reset push button</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Handwheel selector X</source>
        <translation>Handwheel selector X</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Handwheel selector Y</source>
        <translation>Handwheel selector Y</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Handwheel selector Z (tilt)</source>
        <translation>Handwheel selector Z (tilt)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Handwheel multiplier x10</source>
        <translation>Handwheel multiplier x10</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Handwheel multiplier x100</source>
        <translation>Handwheel multiplier x100</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Jog enable button</source>
        <translation>Jog enable button</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Extend centering</source>
        <translation>Extend centering</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Close clamps</source>
        <translation>Close clamps</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Spindle contactor</source>
        <translation>Spindle contactor</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Green lamp</source>
        <translation>Green lamp</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Yellow lamp</source>
        <translation>Yellow lamp</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Red lamp</source>
        <translation>Red lamp</translation>
    </message>
</context>
<context>
    <name>Keypad</name>
    <message>
        <location filename="../../app/screens/widgets/keypad.py" line="+284" />
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <location line="+1" />
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Allowed: whole number from %1 to %2%3</source>
        <translation>Allowed: whole number from %1 to %2%3</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Allowed: %1 to %2%3, or empty</source>
        <translation>Allowed: %1 to %2%3, or empty</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Allowed: %1 to %2%3</source>
        <translation>Allowed: %1 to %2%3</translation>
    </message>
    <message>
        <location line="+118" />
        <source>Enter a number. %1</source>
        <translation>Enter a number. %1</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1%2 is outside the allowed range.</source>
        <translation>%1%2 is outside the allowed range.</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Enter both the numerator and the denominator.</source>
        <translation>Enter both the numerator and the denominator.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>The denominator must not be 0.</source>
        <translation>The denominator must not be 0.</translation>
    </message>
    <message>
        <location line="+33" />
        <source>Enter your PIN.</source>
        <translation>Enter your PIN.</translation>
    </message>
</context>
<context>
    <name>MachineText</name>
    <message>
        <location filename="catalogue_strings.py" line="-419" />
        <source>%1</source>
        <translation>%1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 is not possible while %2</source>
        <translation>%1 is not possible while %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 still in fault %2</source>
        <translation>%1 still in fault %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1+ limit switch is active: jog %1 in the - direction only</source>
        <translation>%1+ limit switch is active: jog %1 in the - direction only</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1- limit switch is active: jog %1 in the + direction only</source>
        <translation>%1- limit switch is active: jog %1 in the + direction only</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1: Resume or Abandon</source>
        <translation>%1: Resume or Abandon</translation>
    </message>
    <message>
        <location line="+1" />
        <source>DC link over-voltage</source>
        <translation>DC link over-voltage</translation>
    </message>
    <message>
        <location line="+1" />
        <source>USB pendant ignored: it jogs only on the Manual screen</source>
        <translation>USB pendant ignored: it jogs only on the Manual screen</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a board is on the table and not clamped: clamp it or take it off before the spindle starts</source>
        <translation>a board is on the table and not clamped: clamp it or take it off before the spindle starts</translation>
    </message>
    <message>
        <location line="+4" />
        <source>a board is on the table and the axes do not know where they are: take the board off before homing</source>
        <translation>a board is on the table and the axes do not know where they are: take the board off before homing</translation>
    </message>
    <message>
        <location line="+4" />
        <source>a board is on the table: moving clear of it before homing</source>
        <translation>a board is on the table: moving clear of it before homing</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a board is partly cut: Resume or Abandon it</source>
        <translation>a board is partly cut: Resume or Abandon it</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a board is partly cut: Resume or Abandon it first</source>
        <translation>a board is partly cut: Resume or Abandon it first</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a cycle is already running</source>
        <translation>a cycle is already running</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a step of 0 moves nothing</source>
        <translation>a step of 0 moves nothing</translation>
    </message>
    <message>
        <location line="+1" />
        <source>abandoning the board</source>
        <translation>abandoning the board</translation>
    </message>
    <message>
        <location line="+1" />
        <source>already in manual mode</source>
        <translation>already in manual mode</translation>
    </message>
    <message>
        <location line="+1" />
        <source>an axis lost its home position</source>
        <translation>an axis lost its home position</translation>
    </message>
    <message>
        <location line="+1" />
        <source>axes are not homed: abandon the board (their position is unknown)</source>
        <translation>axes are not homed: abandon the board (their position is unknown)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>axes are not homed: home the machine first</source>
        <translation>axes are not homed: home the machine first</translation>
    </message>
    <message>
        <location line="+5" />
        <source>axis %1 is at its lower soft limit %2</source>
        <translation>axis %1 is at its lower soft limit %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>axis %1 is at its soft limit</source>
        <translation>axis %1 is at its soft limit</translation>
    </message>
    <message>
        <location line="-5" />
        <source>axis %1 is above its upper soft limit %2 (at %3): only motion back toward the range is allowed</source>
        <oldsource>axis %1 is beyond its soft limit %2 = %3 (%4): only motion back toward the range is allowed</oldsource>
        <translation>axis %1 is above its upper soft limit %2 (at %3): only motion back toward the range is allowed</translation>
    </message>
    <message>
        <location line="+6" />
        <source>axis %1 is at its upper soft limit %2</source>
        <translation>axis %1 is at its upper soft limit %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>axis %1 is below its lower soft limit %2 (at %3): only motion back toward the range is allowed</source>
        <translation>axis %1 is below its lower soft limit %2 (at %3): only motion back toward the range is allowed</translation>
    </message>
    <message>
        <location line="+4" />
        <source>axis %1 is moving: release the jog first</source>
        <translation>axis %1 is moving: release the jog first</translation>
    </message>
    <message>
        <location line="+1" />
        <source>axis %1 is not allowed: X, Y or Z</source>
        <translation>axis %1 is not allowed: X, Y or Z</translation>
    </message>
    <message>
        <location line="+1" />
        <source>axis %1 stopped: the screen stopped confirming the jog</source>
        <translation>axis %1 stopped: the screen stopped confirming the jog</translation>
    </message>
    <message>
        <location line="+1" />
        <source>axis %1, fault code %2</source>
        <translation>axis %1, fault code %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>axis %1: drive did not enable within %2 s</source>
        <translation>axis %1: drive did not enable within %2 s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>axis %1: drive fault %2 while homing</source>
        <translation>axis %1: drive fault %2 while homing</translation>
    </message>
    <message>
        <location line="+1" />
        <source>axis %1: drive not enabled while moving (%2)</source>
        <translation>axis %1: drive not enabled while moving (%2)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>axis %1: following error %2 %3 exceeds %4 %3</source>
        <translation>axis %1: following error %2 %3 exceeds %4 %3</translation>
    </message>
    <message>
        <location line="+1" />
        <source>axis %1: homing did not start within %2 s</source>
        <translation>axis %1: homing did not start within %2 s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>axis %1: homing ended without finding the home switch</source>
        <translation>axis %1: homing ended without finding the home switch</translation>
    </message>
    <message>
        <location line="+1" />
        <source>axis %1: negative limit switch at %2 %3</source>
        <translation>axis %1: negative limit switch at %2 %3</translation>
    </message>
    <message>
        <location line="+1" />
        <source>axis %1: no feedback from its drive</source>
        <translation>axis %1: no feedback from its drive</translation>
    </message>
    <message>
        <location line="+1" />
        <source>axis %1: not homed after %2 s</source>
        <translation>axis %1: not homed after %2 s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>axis %1: positive limit switch at %2 %3</source>
        <translation>axis %1: positive limit switch at %2 %3</translation>
    </message>
    <message>
        <location line="+1" />
        <source>axis %1: setpoint %2 %3 outside the travel %4 to %5 %3</source>
        <translation>axis %1: setpoint %2 %3 outside the travel %4 to %5 %3</translation>
    </message>
    <message>
        <location line="+1" />
        <source>board abandoned and unclamped: take it off (nothing moved: check that the cutter is clear of it)</source>
        <translation>board abandoned and unclamped: take it off (nothing moved: check that the cutter is clear of it)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>board abandoned: take it off</source>
        <translation>board abandoned: take it off</translation>
    </message>
    <message>
        <location line="+1" />
        <source>centering device not extended after %1 s</source>
        <translation>centering device not extended after %1 s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>centering device not retracted after %1 s</source>
        <translation>centering device not retracted after %1 s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>clamps not closed after %1 s</source>
        <translation>clamps not closed after %1 s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>clamps not open after %1 s</source>
        <translation>clamps not open after %1 s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>clipped to the lower soft limit %1</source>
        <translation>clipped to the lower soft limit %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>clipped to the upper soft limit %1</source>
        <translation>clipped to the upper soft limit %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>close the guard first</source>
        <translation>close the guard first</translation>
    </message>
    <message>
        <location line="+1" />
        <source>communication not restored</source>
        <translation>communication not restored</translation>
    </message>
    <message>
        <location line="+1" />
        <source>drive over-temperature</source>
        <translation>drive over-temperature</translation>
    </message>
    <message>
        <location line="+1" />
        <source>emergency stop still pressed</source>
        <translation>emergency stop still pressed</translation>
    </message>
    <message>
        <location line="+1" />
        <source>feed override %1 % is not allowed: 0 to 120 %</source>
        <translation>feed override %1 % is not allowed: 0 to 120 %</translation>
    </message>
    <message>
        <location line="+1" />
        <source>following error</source>
        <translation>following error</translation>
    </message>
    <message>
        <location line="+1" />
        <source>go to position refused: %1</source>
        <translation>go to position refused: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>go to position: %1 = %2 is not allowed: %3 to %4</source>
        <translation>go to position: %1 = %2 is not allowed: %3 to %4</translation>
    </message>
    <message>
        <location line="+1" />
        <source>handwheel ignored: it jogs only on the Manual screen</source>
        <translation>handwheel ignored: it jogs only on the Manual screen</translation>
    </message>
    <message>
        <location line="+1" />
        <source>heartbeat or life guard</source>
        <translation>heartbeat or life guard</translation>
    </message>
    <message>
        <location line="+1" />
        <source>hold the enable button to jog with the handwheel or the joystick</source>
        <translation>hold the enable button to jog with the handwheel or the joystick</translation>
    </message>
    <message>
        <location line="+3" />
        <source>homing refused: %1</source>
        <translation>homing refused: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>jog %1 refused: the cutter is at the board's keep-out (a board is on the table)</source>
        <translation>jog %1 refused: the cutter is at the board's keep-out (a board is on the table)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>jog %1 stops at %2, the edge of the board's keep-out</source>
        <translation>jog %1 stops at %2, the edge of the board's keep-out</translation>
    </message>
    <message>
        <location line="+1" />
        <source>jog %1 was stopped: no refresh from the screen for %2 s; release the button and press it again</source>
        <translation>jog %1 was stopped: no refresh from the screen for %2 s; release the button and press it again</translation>
    </message>
    <message>
        <location line="+4" />
        <source>jog direction %1 is not allowed: -1 or 1</source>
        <translation>jog direction %1 is not allowed: -1 or 1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>joystick %1 reads %2 counts off its centre at start-up: let it go, it is calibrated once at rest</source>
        <translation>joystick %1 reads %2 counts off its centre at start-up: let it go, it is calibrated once at rest</translation>
    </message>
    <message>
        <location line="+4" />
        <source>joystick ignored: it jogs only on the Manual screen</source>
        <translation>joystick ignored: it jogs only on the Manual screen</translation>
    </message>
    <message>
        <location line="+1" />
        <source>leave manual mode first</source>
        <translation>leave manual mode first</translation>
    </message>
    <message>
        <location line="+1" />
        <source>limit switch</source>
        <translation>limit switch</translation>
    </message>
    <message>
        <location line="+1" />
        <source>machine is busy (automatic): stop it first</source>
        <translation>machine is busy (automatic): stop it first</translation>
    </message>
    <message>
        <location line="+1" />
        <source>machine is busy (homing): stop it first</source>
        <translation>machine is busy (homing): stop it first</translation>
    </message>
    <message>
        <location line="+1" />
        <source>machine is busy (stopping): stop it first</source>
        <translation>machine is busy (stopping): stop it first</translation>
    </message>
    <message>
        <location line="+1" />
        <source>machine is in emergency stop: press Reset first</source>
        <translation>machine is in emergency stop: press Reset first</translation>
    </message>
    <message>
        <location line="+1" />
        <source>machine is in emergency stop: release the emergency stop button, then press Reset</source>
        <translation>machine is in emergency stop: release the emergency stop button, then press Reset</translation>
    </message>
    <message>
        <location line="+4" />
        <source>machine is in error: press Reset first</source>
        <translation>machine is in error: press Reset first</translation>
    </message>
    <message>
        <location line="+1" />
        <source>machine is still starting up</source>
        <translation>machine is still starting up</translation>
    </message>
    <message>
        <location line="+1" />
        <source>no board is partly cut</source>
        <translation>no board is partly cut</translation>
    </message>
    <message>
        <location line="+1" />
        <source>no connection to the machine</source>
        <translation>no connection to the machine</translation>
    </message>
    <message>
        <location line="+1" />
        <source>no reading within %1 s</source>
        <translation>no reading within %1 s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>not in manual mode</source>
        <translation>not in manual mode</translation>
    </message>
    <message>
        <location line="+1" />
        <source>not possible while automatic</source>
        <translation>not possible while automatic</translation>
    </message>
    <message>
        <location line="+1" />
        <source>not possible while homing</source>
        <translation>not possible while homing</translation>
    </message>
    <message>
        <location line="+1" />
        <source>not possible while manual</source>
        <translation>not possible while manual</translation>
    </message>
    <message>
        <location line="+1" />
        <source>not possible while not homed</source>
        <translation>not possible while not homed</translation>
    </message>
    <message>
        <location line="+1" />
        <source>not possible while ready</source>
        <translation>not possible while ready</translation>
    </message>
    <message>
        <location line="+1" />
        <source>not possible while stopping</source>
        <translation>not possible while stopping</translation>
    </message>
    <message>
        <location line="+1" />
        <source>nothing is moving</source>
        <translation>nothing is moving</translation>
    </message>
    <message>
        <location line="+1" />
        <source>nothing to reset</source>
        <translation>nothing to reset</translation>
    </message>
    <message>
        <location line="+1" />
        <source>only on the simulated machine</source>
        <translation>only on the simulated machine</translation>
    </message>
    <message>
        <location line="+1" />
        <source>open the Manual screen to jog</source>
        <translation>open the Manual screen to jog</translation>
    </message>
    <message>
        <location line="+1" />
        <source>over-current</source>
        <translation>over-current</translation>
    </message>
    <message>
        <location line="+1" />
        <source>position sensor</source>
        <translation>position sensor</translation>
    </message>
    <message>
        <location line="+1" />
        <source>recipe %1 does not exist</source>
        <translation>recipe %1 does not exist</translation>
    </message>
    <message>
        <location line="+1" />
        <source>recipe %1 has a fixed tilt: it makes no barrel</source>
        <translation>recipe %1 has a fixed tilt: it makes no barrel</translation>
    </message>
    <message>
        <location line="+1" />
        <source>recipe %1 has been changed since it was selected: the machine keeps the version it was selected with; select it again to cut the new version</source>
        <translation>recipe %1 has been changed since it was selected: the machine keeps the version it was selected with; select it again to cut the new version</translation>
    </message>
    <message>
        <location line="+4" />
        <source>recipe %1 no longer exists: abandon the board</source>
        <translation>recipe %1 no longer exists: abandon the board</translation>
    </message>
    <message>
        <location line="+1" />
        <source>recipe %1, selected on the machine, has been deleted: select a recipe</source>
        <translation>recipe %1, selected on the machine, has been deleted: select a recipe</translation>
    </message>
    <message>
        <location line="+3" />
        <source>reconnection failed: %1</source>
        <translation>reconnection failed: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>release the emergency stop first</source>
        <translation>release the emergency stop first</translation>
    </message>
    <message>
        <location line="+1" />
        <source>reset done</source>
        <translation>reset done</translation>
    </message>
    <message>
        <location line="+1" />
        <source>reset failed</source>
        <translation>reset failed</translation>
    </message>
    <message>
        <location line="+1" />
        <source>resuming the board</source>
        <translation>resuming the board</translation>
    </message>
    <message>
        <location line="+1" />
        <source>select a recipe first</source>
        <translation>select a recipe first</translation>
    </message>
    <message>
        <location line="+1" />
        <source>spindle not running after %1 s</source>
        <translation>spindle not running after %1 s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>step of %1 refused: the cutter would enter the board's keep-out at %2 (a board is on the table)</source>
        <translation>step of %1 refused: the cutter would enter the board's keep-out at %2 (a board is on the table)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the USB pendant is jogging: let it and the axes come to rest first</source>
        <translation>the USB pendant is jogging: let it and the axes come to rest first</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the axes are going to a position: wait, or press Stop</source>
        <translation>the axes are going to a position: wait, or press Stop</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the board is clamped: unclamp it first</source>
        <translation>the board is clamped: unclamp it first</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the board was unclamped: it may have moved, abandon it</source>
        <translation>the board was unclamped: it may have moved, abandon it</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the counter moved %1 counts in one read; a hand turns at most %2</source>
        <translation>the counter moved %1 counts in one read; a hand turns at most %2</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the guard was opened</source>
        <translation>the guard was opened</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the handwheel is jogging: let it and the axes come to rest first</source>
        <translation>the handwheel is jogging: let it and the axes come to rest first</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the joystick is jogging: let it go and the axes stop first</source>
        <translation>the joystick is jogging: let it go and the axes stop first</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the oldest has waited %1 s</source>
        <translation>the oldest has waited %1 s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the part-present sensor went off during the cycle</source>
        <translation>the part-present sensor went off during the cycle</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the partly cut board is no longer on the table</source>
        <translation>the partly cut board is no longer on the table</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the recipe selected before the restart cannot be read: select a recipe</source>
        <translation>the recipe selected before the restart cannot be read: select a recipe</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the screen is jogging: release it and let the axes stop first</source>
        <translation>the screen is jogging: release it and let the axes stop first</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the simulation refused: %1</source>
        <translation>the simulation refused: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the spindle's running signal went off</source>
        <translation>the spindle's running signal went off</translation>
    </message>
    <message>
        <location line="+1" />
        <source>unknown command</source>
        <translation>unknown command</translation>
    </message>
    <message>
        <location line="+1" />
        <source>wait until the cycle has ended</source>
        <translation>wait until the cycle has ended</translation>
    </message>
</context>
<context>
    <name>MainScreen</name>
    <message>
        <location filename="../../app/screens/main_screen.py" line="+282" />
        <source>Main</source>
        <translation>Main</translation>
    </message>
    <message>
        <location line="+25" />
        <source>Recipe</source>
        <translation>Recipe</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Choose recipe…</source>
        <translation>Choose recipe…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Previous recipe</source>
        <translation>Previous recipe</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Next recipe</source>
        <translation>Next recipe</translation>
    </message>
    <message>
        <location line="+1" />
        <source>▶  START</source>
        <translation>▶  START</translation>
    </message>
    <message>
        <location line="+1" />
        <source>■  STOP</source>
        <translation>■  STOP</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Home</source>
        <translation>Home</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Reset</source>
        <translation>Reset</translation>
    </message>
    <message>
        <location line="-24" />
        <source>Put a board in
(simulation)</source>
        <translation>Put a board in
(simulation)</translation>
    </message>
    <message>
        <location line="-2" />
        <source>Replace the board
(simulation)</source>
        <translation>Replace the board
(simulation)</translation>
    </message>
    <message>
        <location line="+28" />
        <source>New
shift</source>
        <translation>New
shift</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Pieces this shift</source>
        <translation>Pieces this shift</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Pieces total</source>
        <translation>Pieces total</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+169" />
        <source>Last width</source>
        <translation>Last width</translation>
    </message>
    <message>
        <location line="-168" />
        <source>Last cycle</source>
        <translation>Last cycle</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Cycle</source>
        <translation>Cycle</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Waited</source>
        <translation>Waited</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Remaining</source>
        <translation>Remaining</translation>
    </message>
    <message>
        <location line="+2" />
        <source>All inputs and outputs</source>
        <translation>All inputs and outputs</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Last cycle by step</source>
        <translation>Last cycle by step</translation>
    </message>
    <message>
        <location line="+2" />
        <source>NOT HOMED</source>
        <translation>NOT HOMED</translation>
    </message>
    <message>
        <location line="+27" />
        <source>There are no recipes yet: create one on Recipes.</source>
        <translation>There are no recipes yet: create one on Recipes.</translation>
    </message>
    <message>
        <location line="+27" />
        <source>Resume the cut</source>
        <translation>Resume the cut</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Abandon the board</source>
        <translation>Abandon the board</translation>
    </message>
    <message>
        <location line="+10" />
        <source>A board is partly cut</source>
        <translation>A board is partly cut</translation>
    </message>
    <message>
        <location line="+6" />
        <source>New shift</source>
        <translation>New shift</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Start counting the pieces of a new shift from 0? The total count is kept; the operator of the new shift then enters his name.</source>
        <translation>Start counting the pieces of a new shift from 0? The total count is kept; the operator of the new shift then enters his name.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Start new shift</source>
        <translation>Start new shift</translation>
    </message>
    <message>
        <location line="+9" />
        <source>No recipe selected</source>
        <translation>No recipe selected</translation>
    </message>
    <message>
        <location line="+2" />
        <source>No. %1</source>
        <translation>No. %1</translation>
    </message>
    <message>
        <location line="+55" />
        <source>+%1 waiting</source>
        <translation>+%1 waiting</translation>
    </message>
    <message>
        <location line="+12" />
        <source>Board width</source>
        <translation>Board width</translation>
    </message>
    <message>
        <location line="+17" />
        <source>Take the finished board off</source>
        <translation>Take the finished board off</translation>
    </message>
    <message>
        <location line="+6" />
        <source>No cycle running</source>
        <translation>No cycle running</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Move to go</source>
        <translation>Move to go</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Step to go</source>
        <translation>Step to go</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Path speed</source>
        <translation>Path speed</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Moving clear of the board</source>
        <translation>Moving clear of the board</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Homing axis %1</source>
        <translation>Homing axis %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Homing done</source>
        <translation>Homing done</translation>
    </message>
    <message>
        <location line="+16" />
        <source>Axis %1</source>
        <translation>Axis %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>homed ✓</source>
        <translation>homed ✓</translation>
    </message>
    <message>
        <location line="+2" />
        <source>homing…</source>
        <translation>homing…</translation>
    </message>
    <message>
        <location line="+2" />
        <source>waiting</source>
        <translation>waiting</translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <location filename="../../app/screens/main_window.py" line="+190" />
        <source>(+%1 more)</source>
        <translation>(+%1 more)</translation>
    </message>
    <message>
        <location line="+2" />
        <location line="+204" />
        <source>Alarms</source>
        <translation>Alarms</translation>
    </message>
    <message>
        <location line="-197" />
        <source>The machine is not running.</source>
        <translation>The machine is not running.</translation>
    </message>
    <message>
        <location line="+29" />
        <source>Service</source>
        <translation>Service</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+7" />
        <location line="+4" />
        <source>Log out</source>
        <translation>Log out</translation>
    </message>
    <message>
        <location line="-11" />
        <location line="+213" />
        <location line="+2" />
        <source>Leave the kiosk</source>
        <translation>Leave the kiosk</translation>
    </message>
    <message>
        <location line="-207" />
        <source>Log out %1 and go back to the operator level?</source>
        <translation>Log out %1 and go back to the operator level?</translation>
    </message>
    <message>
        <location line="+9" />
        <source>User</source>
        <translation>User</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Log in with a PIN</source>
        <translation>Log in with a PIN</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Name the operator of this shift</source>
        <translation>Name the operator of this shift</translation>
    </message>
    <message>
        <location line="+8" />
        <source>Log in: enter your PIN</source>
        <translation>Log in: enter your PIN</translation>
    </message>
    <message>
        <location line="+31" />
        <source>Operator of this shift: your name</source>
        <translation>Operator of this shift: your name</translation>
    </message>
    <message>
        <location line="+24" />
        <source>Wrong PIN.</source>
        <translation>Wrong PIN.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>This needs the %1 level; %2 is %3.</source>
        <translation>This needs the %1 level; %2 is %3.</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Checking…</source>
        <translation>Checking…</translation>
    </message>
    <message>
        <location line="+14" />
        <source>This needs the %1 level: enter a PIN</source>
        <translation>This needs the %1 level: enter a PIN</translation>
    </message>
    <message>
        <location line="+16" />
        <source>Operator of this shift: %1</source>
        <translation>Operator of this shift: %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Logged out.</source>
        <translation>Logged out.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Logged in: %1 (%2)</source>
        <translation>Logged in: %1 (%2)</translation>
    </message>
    <message>
        <location line="+20" />
        <location line="+23" />
        <source>Language</source>
        <translation>Language</translation>
    </message>
    <message>
        <location line="-11" />
        <source>Main</source>
        <translation>Main</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Recipes</source>
        <translation>Recipes</translation>
    </message>
    <message>
        <location line="+1" />
        <source>System</source>
        <translation>System</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Manual</source>
        <translation>Manual</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Production</source>
        <translation>Production</translation>
    </message>
    <message>
        <location line="+4" />
        <location line="+57" />
        <location line="+2" />
        <source>Shut down</source>
        <translation>Shut down</translation>
    </message>
    <message>
        <location line="-58" />
        <source>Log in or out</source>
        <translation>Log in or out</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Stave jointer</source>
        <translation>Stave jointer</translation>
    </message>
    <message>
        <location line="+38" />
        <source>Stop the machine safely and leave the operator screen for the console?</source>
        <translation>Stop the machine safely and leave the operator screen for the console?</translation>
    </message>
    <message>
        <location line="+16" />
        <source>Stop the machine safely and close the program?</source>
        <translation>Stop the machine safely and close the program?</translation>
    </message>
</context>
<context>
    <name>ManualScreen</name>
    <message>
        <location filename="../../app/screens/manual_screen.py" line="+235" />
        <source>Manual</source>
        <translation>Manual</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Enter manual mode</source>
        <translation>Enter manual mode</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Tilt</source>
        <translation>Tilt</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Continuous</source>
        <translation>Continuous</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Step</source>
        <translation>Step</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Step size (mm for X-Y; tilt 0.1° or 1°)</source>
        <translation>Step size (mm for X-Y; tilt 0.1° or 1°)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Jog speed</source>
        <translation>Jog speed</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Jog acceleration</source>
        <translation>Jog acceleration</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Home (find the reference position)</source>
        <translation>Home (find the reference position)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Home %1</source>
        <translation>Home %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Go to…</source>
        <translation>Go to…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Go to a position typed on the keypad</source>
        <translation>Go to a position typed on the keypad</translation>
    </message>
    <message>
        <location line="+1" />
        <source>All</source>
        <translation>All</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Home all axes</source>
        <translation>Home all axes</translation>
    </message>
    <message>
        <location line="+2" />
        <source>NOT HOMED</source>
        <translation>NOT HOMED</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Waiting for the machine…</source>
        <translation>Waiting for the machine…</translation>
    </message>
    <message>
        <location line="+53" />
        <source>Jog speed %1</source>
        <translation>Jog speed %1</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Jog acceleration %1</source>
        <translation>Jog acceleration %1</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Log in to change parameters.</source>
        <translation>Log in to change parameters.</translation>
    </message>
    <message>
        <location line="+24" />
        <source>Go to X</source>
        <translation>Go to X</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Go to Y</source>
        <translation>Go to Y</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Go to tilt</source>
        <translation>Go to tilt</translation>
    </message>
    <message>
        <location line="+40" />
        <source>Start the spindle?</source>
        <translation>Start the spindle?</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The cutter starts turning. Keep clear of it.</source>
        <translation>The cutter starts turning. Keep clear of it.</translation>
    </message>
    <message>
        <location line="+14" />
        <source>Manual mode: hold a button to jog.</source>
        <translation>Manual mode: hold a button to jog.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Not in manual mode.</source>
        <translation>Not in manual mode.</translation>
    </message>
    <message>
        <location line="+34" />
        <source>Open clamps</source>
        <translation>Open clamps</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Close clamps</source>
        <translation>Close clamps</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Spindle OFF</source>
        <translation>Spindle OFF</translation>
    </message>
    <message>
        <location line="-64" />
        <location line="+64" />
        <source>Spindle ON</source>
        <translation>Spindle ON</translation>
    </message>
</context>
<context>
    <name>MessageOverlay</name>
    <message>
        <location filename="../../app/screens/widgets/dialogs.py" line="+21" />
        <source>OK</source>
        <translation>OK</translation>
    </message>
</context>
<context>
    <name>OpcuaPage</name>
    <message>
        <location filename="../../app/screens/opcua_page.py" line="+89" />
        <source>OPC UA plant connection</source>
        <translation>OPC UA plant connection</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Client certificates refused (not trusted yet). A plant system connects only after its certificate is trusted:</source>
        <translation>Client certificates refused (not trusted yet). A plant system connects only after its certificate is trusted:</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Certificate</source>
        <translation>Certificate</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Application</source>
        <translation>Application</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Valid until</source>
        <translation>Valid until</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Trust the selected certificate</source>
        <translation>Trust the selected certificate</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Refresh</source>
        <translation>Refresh</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Server off ([opcua] enabled = false in the configuration).</source>
        <translation>Server off ([opcua] enabled = false in the configuration).</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Server running: plant systems can connect.</source>
        <translation>Server running: plant systems can connect.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Server not running: %1</source>
        <translation>Server not running: %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Server not running: its process has ended (see opcua.log).</source>
        <translation>Server not running: its process has ended (see opcua.log).</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Server starting (loading the information model)...</source>
        <translation>Server starting (loading the information model)...</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Warning: security policy None is on: clients may connect without signing or encryption.</source>
        <translation>Warning: security policy None is on: clients may connect without signing or encryption.</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Warning: anonymous access is on: clients may read without a user.</source>
        <translation>Warning: anonymous access is on: clients may read without a user.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Use these for commissioning only ([opcua] configuration).</source>
        <translation>Use these for commissioning only ([opcua] configuration).</translation>
    </message>
    <message>
        <location line="+15" />
        <source>Endpoint: %1</source>
        <translation>Endpoint: %1</translation>
    </message>
    <message>
        <location line="+59" />
        <source>Certificate %1 trusted by %2 (logged).</source>
        <translation>Certificate %1 trusted by %2 (logged).</translation>
    </message>
</context>
<context>
    <name>Parameters</name>
    <message>
        <location filename="catalogue_strings.py" line="+251" />
        <source>Distance beyond the board's right end where the tilt changes sides</source>
        <translation>Distance beyond the board's right end where the tilt changes sides</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Height of the tilt pivot above the table (Hm)</source>
        <translation>Height of the tilt pivot above the table (Hm)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Home position of X</source>
        <translation>Home position of X</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Home position of Y</source>
        <translation>Home position of Y</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Home tilt of the router (Z)</source>
        <translation>Home tilt of the router (Z)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Lead-in before x = 0 and lead-out after x = L (longer than the tool radius)</source>
        <translation>Lead-in before x = 0 and lead-out after x = L (longer than the tool radius)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Length of one shift</source>
        <translation>Length of one shift</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Most material the router takes off one side in one pass (more: roughing passes first)</source>
        <translation>Most material the router takes off one side in one pass (more: roughing passes first)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Number of shifts per day</source>
        <translation>Number of shifts per day</translation>
    </message>
    <message>
        <location line="+1" />
        <source>P0: machine X of the stave's left end</source>
        <translation>P0: machine X of the stave's left end</translation>
    </message>
    <message>
        <location line="+1" />
        <source>P0: machine Y of the table centre line</source>
        <translation>P0: machine Y of the table centre line</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Radius of the router cutter</source>
        <translation>Radius of the router cutter</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Soft limit: highest X</source>
        <translation>Soft limit: highest X</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Soft limit: highest Y</source>
        <translation>Soft limit: highest Y</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Soft limit: highest tilt</source>
        <translation>Soft limit: highest tilt</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Soft limit: lowest X</source>
        <translation>Soft limit: lowest X</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Soft limit: lowest Y</source>
        <translation>Soft limit: lowest Y</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Soft limit: lowest tilt</source>
        <translation>Soft limit: lowest tilt</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Start of the first shift of the day, hours after midnight (6.5 = 06:30)</source>
        <translation>Start of the first shift of the day, hours after midnight (6.5 = 06:30)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Tilt (Z) acceleration</source>
        <translation>Tilt (Z) acceleration</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Tilt (Z) jerk limit</source>
        <translation>Tilt (Z) jerk limit</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Tilt (Z) jog acceleration</source>
        <translation>Tilt (Z) jog acceleration</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Tilt (Z) jog speed</source>
        <translation>Tilt (Z) jog speed</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Tilt (Z) speed</source>
        <translation>Tilt (Z) speed</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Tolerance of the stave-side solver (root of the cubic in D)</source>
        <translation>Tolerance of the stave-side solver (root of the cubic in D)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>X-Y acceleration</source>
        <translation>X-Y acceleration</translation>
    </message>
    <message>
        <location line="+1" />
        <source>X-Y cutting feed</source>
        <translation>X-Y cutting feed</translation>
    </message>
    <message>
        <location line="+1" />
        <source>X-Y jerk limit</source>
        <translation>X-Y jerk limit</translation>
    </message>
    <message>
        <location line="+1" />
        <source>X-Y jog acceleration</source>
        <translation>X-Y jog acceleration</translation>
    </message>
    <message>
        <location line="+1" />
        <source>X-Y jog speed</source>
        <translation>X-Y jog speed</translation>
    </message>
    <message>
        <location line="+1" />
        <source>X-Y speed of non-cutting moves</source>
        <translation>X-Y speed of non-cutting moves</translation>
    </message>
</context>
<context>
    <name>PendantStatus</name>
    <message>
        <location filename="../../app/screens/widgets/pendant_status.py" line="+23" />
        <source>the screen</source>
        <translation>the screen</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the handwheel</source>
        <translation>the handwheel</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the joystick</source>
        <translation>the joystick</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the USB pendant</source>
        <translation>the USB pendant</translation>
    </message>
    <message>
        <location line="+2" />
        <source>nobody (all at rest)</source>
        <translation>nobody (all at rest)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Jogging: %1</source>
        <translation>Jogging: %1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Handwheel: %1 ×%2</source>
        <translation>Handwheel: %1 ×%2</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Handwheel: off</source>
        <translation>Handwheel: off</translation>
    </message>
    <message>
        <location line="+3" />
        <source>USB pendant connected</source>
        <translation>USB pendant connected</translation>
    </message>
</context>
<context>
    <name>PinLockoutBar</name>
    <message>
        <location filename="../../app/screens/pin_lockout.py" line="+53" />
        <source>Unlock PIN entry</source>
        <translation>Unlock PIN entry</translation>
    </message>
    <message>
        <location line="+5" />
        <source>PIN entry is locked after repeated wrong PINs until %1. A service user can unlock it now.</source>
        <translation>PIN entry is locked after repeated wrong PINs until %1. A service user can unlock it now.</translation>
    </message>
    <message>
        <location line="+19" />
        <source>PIN entry unlocked by %1 (logged).</source>
        <translation>PIN entry unlocked by %1 (logged).</translation>
    </message>
</context>
<context>
    <name>ProductionScreen</name>
    <message>
        <location filename="../../app/screens/production_screen.py" line="+152" />
        <source>Production</source>
        <translation>Production</translation>
    </message>
    <message>
        <location line="+4" />
        <source>This shift</source>
        <translation>This shift</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Last shift</source>
        <translation>Last shift</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Today</source>
        <translation>Today</translation>
    </message>
    <message>
        <location line="+1" />
        <source>7 days</source>
        <translation>7 days</translation>
    </message>
    <message>
        <location line="+1" />
        <source>30 days</source>
        <translation>30 days</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Export CSV…</source>
        <translation>Export CSV…</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Staves per hour</source>
        <translation>Staves per hour</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Cycle time per stave, s:</source>
        <translation>Cycle time per stave, s:</translation>
    </message>
    <message>
        <location line="+2" />
        <source>cycle</source>
        <translation>cycle</translation>
    </message>
    <message>
        <location line="+2" />
        <source>bound</source>
        <translation>bound</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Board widths, mm</source>
        <translation>Board widths, mm</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Alarms per hour</source>
        <translation>Alarms per hour</translation>
    </message>
    <message>
        <location line="+12" />
        <source>Good</source>
        <translation>Good</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Aborted</source>
        <translation>Aborted</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Rejected</source>
        <translation>Rejected</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1 per hour</source>
        <translation>%1 per hour</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Alarms %1</source>
        <translation>Alarms %1</translation>
    </message>
    <message>
        <location line="+12" />
        <source>Reading…</source>
        <translation>Reading…</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Nothing produced in this range.</source>
        <translation>Nothing produced in this range.</translation>
    </message>
    <message>
        <location line="+42" />
        <source>Not read: %1</source>
        <translation>Not read: %1</translation>
    </message>
    <message>
        <location line="+18" />
        <source>Export production</source>
        <translation>Export production</translation>
    </message>
    <message>
        <location line="+19" />
        <source>Export failed</source>
        <translation>Export failed</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1 production records written to %2.</source>
        <translation>%1 production records written to %2.</translation>
    </message>
</context>
<context>
    <name>RecipeChooser</name>
    <message>
        <location filename="../../app/screens/recipe_chooser.py" line="+52" />
        <source>Choose a recipe</source>
        <translation>Choose a recipe</translation>
    </message>
    <message>
        <location line="+16" />
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <location line="+43" />
        <source>No recipe matches.</source>
        <translation>No recipe matches.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 of %2 recipes</source>
        <translation>%1 of %2 recipes</translation>
    </message>
</context>
<context>
    <name>RecipeFilterBar</name>
    <message>
        <location filename="../../app/screens/recipe_filter.py" line="+114" />
        <source>All</source>
        <translation>All</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Fixed</source>
        <translation>Fixed</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Round</source>
        <translation>Round</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Oval</source>
        <translation>Oval</translation>
    </message>
    <message>
        <location line="+12" />
        <source>Show recipes of barrel type</source>
        <translation>Show recipes of barrel type</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Search recipes by name or number</source>
        <translation>Search recipes by name or number</translation>
    </message>
    <message>
        <location line="+25" />
        <source>Search…</source>
        <translation>Search…</translation>
    </message>
</context>
<context>
    <name>RecipesScreen</name>
    <message>
        <location filename="../../app/screens/recipes_screen.py" line="+379" />
        <location line="+110" />
        <source>Recipes</source>
        <translation>Recipes</translation>
    </message>
    <message>
        <location line="-106" />
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Length L</source>
        <translation>Length L</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Thickness H</source>
        <translation>Thickness H</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Length ratio L1 : L</source>
        <translation>Length ratio L1 : L</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Width ratio W1 : W</source>
        <translation>Width ratio W1 : W</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Side profile</source>
        <translation>Side profile</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Exponent n</source>
        <translation>Exponent n</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Semi-axis a : L/2</source>
        <translation>Semi-axis a : L/2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Drawing (DXF)</source>
        <translation>Drawing (DXF)</translation>
    </message>
    <message>
        <location line="+117" />
        <source>Tilt</source>
        <translation>Tilt</translation>
    </message>
    <message>
        <location line="-115" />
        <source>Tilt α</source>
        <translation>Tilt α</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Barrel diameter</source>
        <translation>Barrel diameter</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Oval: short axis</source>
        <translation>Oval: short axis</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Barrel perimeter</source>
        <translation>Barrel perimeter</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Belly width to cut</source>
        <translation>Belly width to cut</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Note</source>
        <translation>Note</translation>
    </message>
    <message>
        <location line="+41" />
        <source>(optional)</source>
        <translation>(optional)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>0 to below 1/2</source>
        <translation>0 to below 1/2</translation>
    </message>
    <message>
        <location line="+6" />
        <source>1 to %1 characters</source>
        <translation>1 to %1 characters</translation>
    </message>
    <message>
        <location line="+2" />
        <source>optional</source>
        <translation>optional</translation>
    </message>
    <message>
        <location line="+7" />
        <source>the shape of both sides</source>
        <translation>the shape of both sides</translation>
    </message>
    <message>
        <location line="+2" />
        <source>one side, head to head; scaled to L and W</source>
        <translation>one side, head to head; scaled to L and W</translation>
    </message>
    <message>
        <location line="+20" />
        <source>Line–arc–line</source>
        <translation>Line–arc–line</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Single arc</source>
        <translation>Single arc</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Parabola</source>
        <translation>Parabola</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Ellipse arc</source>
        <translation>Ellipse arc</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Superellipse</source>
        <translation>Superellipse</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Drawn (DXF)</source>
        <translation>Drawn (DXF)</translation>
    </message>
    <message>
        <location line="+7" />
        <source>New</source>
        <translation>New</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Copy</source>
        <translation>Copy</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+641" />
        <source>Delete</source>
        <translation>Delete</translation>
    </message>
    <message>
        <location line="-640" />
        <location line="+690" />
        <source>Import</source>
        <translation>Import</translation>
    </message>
    <message>
        <location line="-689" />
        <source>Export</source>
        <translation>Export</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Save</source>
        <translation>Save</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+140" />
        <source>Discard</source>
        <translation>Discard</translation>
    </message>
    <message>
        <location line="-139" />
        <source>Use on machine</source>
        <translation>Use on machine</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Preview</source>
        <translation>Preview</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+447" />
        <source>Board width for the preview</source>
        <translation>Board width for the preview</translation>
    </message>
    <message>
        <location line="-446" />
        <source>G-code, DXF…</source>
        <translation>G-code, DXF…</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Head W1</source>
        <translation>Head W1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Rise D</source>
        <translation>Rise D</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Radius R</source>
        <translation>Radius R</translation>
    </message>
    <message>
        <location line="+19" />
        <source>%1 of %2 recipes</source>
        <translation>%1 of %2 recipes</translation>
    </message>
    <message>
        <location line="+36" />
        <source>%1 to %2 mm</source>
        <translation>%1 to %2 mm</translation>
    </message>
    <message>
        <location line="+5" />
        <source>cuts no board here</source>
        <translation>cuts no board here</translation>
    </message>
    <message>
        <location line="+3" />
        <source>on the machine, %1</source>
        <translation>on the machine, %1</translation>
    </message>
    <message>
        <location line="+63" />
        <source>Unsaved changes</source>
        <translation>Unsaved changes</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Discard the changes to %1?</source>
        <translation>Discard the changes to %1?</translation>
    </message>
    <message>
        <location line="+97" />
        <source>The name %1 is already used by recipe %2.</source>
        <translation>The name %1 is already used by recipe %2.</translation>
    </message>
    <message>
        <location line="+29" />
        <source>Import a side profile (DXF)</source>
        <translation>Import a side profile (DXF)</translation>
    </message>
    <message>
        <location line="+15" />
        <location line="+11" />
        <source>Drawing not imported</source>
        <translation>Drawing not imported</translation>
    </message>
    <message>
        <location line="-6" />
        <source>Layer of the side profile</source>
        <translation>Layer of the side profile</translation>
    </message>
    <message>
        <location line="+25" />
        <source>No recipe</source>
        <translation>No recipe</translation>
    </message>
    <message>
        <location line="+8" />
        <location line="+256" />
        <source>New recipe</source>
        <translation>New recipe</translation>
    </message>
    <message>
        <location line="-254" />
        <source>Recipe %1</source>
        <translation>Recipe %1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>(changed, not saved)</source>
        <translation>(changed, not saved)</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Import a DXF file…</source>
        <translation>Import a DXF file…</translation>
    </message>
    <message>
        <location line="+72" />
        <source>from the barrel, for a %1 mm board</source>
        <translation>from the barrel, for a %1 mm board</translation>
    </message>
    <message>
        <location line="+71" />
        <source>This recipe cuts no board on this machine</source>
        <translation>This recipe cuts no board on this machine</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Boards it cuts on this machine: %1 to %2 mm</source>
        <translation>Boards it cuts on this machine: %1 to %2 mm</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Outside the widths this recipe cuts on this machine</source>
        <translation>Outside the widths this recipe cuts on this machine</translation>
    </message>
    <message>
        <location line="+28" />
        <source>Not saved</source>
        <translation>Not saved</translation>
    </message>
    <message>
        <location line="+0" />
        <source>No user account to save as.</source>
        <translation>No user account to save as.</translation>
    </message>
    <message>
        <location line="+8" />
        <location line="+3" />
        <source>Recipe not saved</source>
        <translation>Recipe not saved</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Recipe %1 saved.</source>
        <translation>Recipe %1 saved.</translation>
    </message>
    <message>
        <location line="+8" />
        <source>Use the new version?</source>
        <translation>Use the new version?</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Recipe %1 is selected on the machine. Cut the saved version from the next board on? Cancel: the machine keeps the version it has.</source>
        <translation>Recipe %1 is selected on the machine. Cut the saved version from the next board on? Cancel: the machine keeps the version it has.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Use the new version</source>
        <translation>Use the new version</translation>
    </message>
    <message>
        <location line="+8" />
        <source>Not changed on the machine</source>
        <translation>Not changed on the machine</translation>
    </message>
    <message>
        <location line="+4" />
        <location line="+12" />
        <source>Recipe %1 selected.</source>
        <translation>Recipe %1 selected.</translation>
    </message>
    <message>
        <location line="+8" />
        <source>New recipe %1</source>
        <translation>New recipe %1</translation>
    </message>
    <message>
        <location line="+15" />
        <source>Name of the copy</source>
        <translation>Name of the copy</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 copy</source>
        <translation>%1 copy</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Choose a new name.</source>
        <translation>Choose a new name.</translation>
    </message>
    <message>
        <location line="+11" />
        <source>Not copied</source>
        <translation>Not copied</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Recipe %1 created.</source>
        <translation>Recipe %1 created.</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Recipe %1 is selected on the machine: select another recipe there first.</source>
        <translation>Recipe %1 is selected on the machine: select another recipe there first.</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Delete recipe</source>
        <translation>Delete recipe</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Delete recipe %1 (%2)? Its last version stays in the recipe history.</source>
        <translation>Delete recipe %1 (%2)? Its last version stays in the recipe history.</translation>
    </message>
    <message>
        <location line="-10" />
        <location line="+28" />
        <source>Not deleted</source>
        <translation>Not deleted</translation>
    </message>
    <message>
        <location line="-757" />
        <source>Barrel type</source>
        <translation>Barrel type</translation>
    </message>
    <message>
        <location line="+52" />
        <source>%1 to below 1</source>
        <translation>%1 to below 1</translation>
    </message>
    <message>
        <location line="+8" />
        <source>the tilt: fixed, or from the barrel</source>
        <translation>the tilt: fixed, or from the barrel</translation>
    </message>
    <message>
        <location line="+12" />
        <source>Fixed tilt</source>
        <translation>Fixed tilt</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Round</source>
        <translation>Round</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Oval</source>
        <translation>Oval</translation>
    </message>
    <message>
        <location line="+688" />
        <source>Recipe %1 deleted.</source>
        <translation>Recipe %1 deleted.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Import recipes</source>
        <translation>Import recipes</translation>
    </message>
    <message>
        <location line="+16" />
        <source>Import failed</source>
        <translation>Import failed</translation>
    </message>
    <message>
        <location line="+5" />
        <source>… and %1 more lines</source>
        <translation>… and %1 more lines</translation>
    </message>
    <message>
        <location line="+11" />
        <source>%1: %2 accepted (%3 new, %4 updated, %5 unchanged), %6 rejected</source>
        <translation>%1: %2 accepted (%3 new, %4 updated, %5 unchanged), %6 rejected</translation>
    </message>
    <message>
        <location line="+10" />
        <source>row %1 (%2)</source>
        <translation>row %1 (%2)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>row %1</source>
        <translation>row %1</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Export recipes</source>
        <translation>Export recipes</translation>
    </message>
    <message>
        <location line="+12" />
        <location line="+50" />
        <source>Export failed</source>
        <translation>Export failed</translation>
    </message>
    <message>
        <location line="-47" />
        <source>%1 recipes written to %2.</source>
        <translation>%1 recipes written to %2.</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Nothing to export</source>
        <translation>Nothing to export</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Select a saved recipe (save the changes first).</source>
        <translation>Select a saved recipe (save the changes first).</translation>
    </message>
    <message>
        <location line="+6" />
        <source>LinuxCNC program, %1</source>
        <translation>LinuxCNC program, %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>LinuxCNC, parametric (every width)</source>
        <translation>LinuxCNC, parametric (every width)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>SINUMERIK program, %1</source>
        <translation>SINUMERIK program, %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>DXF drawing, %1</source>
        <translation>DXF drawing, %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Program for another control</source>
        <translation>Program for another control</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Not exported</source>
        <translation>Not exported</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Write the program</source>
        <translation>Write the program</translation>
    </message>
    <message>
        <location line="+15" />
        <source>Written to %1.</source>
        <translation>Written to %1.</translation>
    </message>
</context>
<context>
    <name>Roles</name>
    <message>
        <location filename="../../app/screens/texts.py" line="-7" />
        <source>Operator</source>
        <translation>Operator</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Technician</source>
        <translation>Technician</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Service</source>
        <translation>Service</translation>
    </message>
</context>
<context>
    <name>RuleText</name>
    <message>
        <location line="-49" />
        <source>This value is not allowed</source>
        <translation>This value is not allowed</translation>
    </message>
    <message>
        <location filename="catalogue_strings.py" line="+1" />
        <source>%1 is not a barrel type: allowed fixed tilt, round or oval</source>
        <translation>%1 is not a barrel type: allowed fixed tilt, round or oval</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 is not a number</source>
        <translation>%1 is not a number</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 is not a text</source>
        <translation>%1 is not a text</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 is not allowed: above 0 and below 1</source>
        <translation>%1 is not allowed: above 0 and below 1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 is not allowed: from 0 to below 1/2 (at 1/2 or more no arc is left)</source>
        <translation>%1 is not allowed: from 0 to below 1/2 (at 1/2 or more no arc is left)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1 is outside the allowed range: %2 to %3 %4</source>
        <translation>%1 is outside the allowed range: %2 to %3 %4</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 is outside the allowed range: empty, or %2 to %3 %4</source>
        <translation>%1 is outside the allowed range: empty, or %2 to %3 %4</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 leaves nothing to cut (the head as wide as the belly): allowed below 1</source>
        <translation>%1 leaves nothing to cut (the head as wide as the belly): allowed below 1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1 makes the head narrower than %2 mm even on a board of %3 mm: allowed %4 to below 1</source>
        <translation>%1 makes the head narrower than %2 mm even on a board of %3 mm: allowed %4 to below 1</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 mm fits no board of this recipe: boards of %2 to %3 mm need a tilt of %4 to %5°</source>
        <translation>%1 mm fits no board of this recipe: boards of %2 to %3 mm need a tilt of %4 to %5°</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 mm has no use with a fixed tilt: leave the short axis empty, or choose an oval barrel</source>
        <translation>%1 mm has no use with a fixed tilt: leave the short axis empty, or choose an oval barrel</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 mm has no use with a round barrel: leave the short axis empty, or choose an oval barrel</source>
        <translation>%1 mm has no use with a round barrel: leave the short axis empty, or choose an oval barrel</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 mm is not allowed: the short axis is %2 mm up to the long axis, %3 mm</source>
        <translation>%1 mm is not allowed: the short axis is %2 mm up to the long axis, %3 mm</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1 mm would make the head %2 mm wide: allowed %3 mm or more</source>
        <translation>%1 mm would make the head %2 mm wide: allowed %3 mm or more</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1° fits no barrel of %2 to %3 mm for the boards of this recipe: allowed %4 to %5°</source>
        <translation>%1° fits no barrel of %2 to %3 mm for the boards of this recipe: allowed %4 to %5°</translation>
    </message>
    <message>
        <location line="+4" />
        <source>A board of %1 mm does not fit a barrel of %2 mm</source>
        <translation>A board of %1 mm does not fit a barrel of %2 mm</translation>
    </message>
    <message>
        <location line="+1" />
        <source>A board of %1 mm is narrower than the stave it should become, %2 mm</source>
        <translation>A board of %1 mm is narrower than the stave it should become, %2 mm</translation>
    </message>
    <message>
        <location line="+3" />
        <source>A board of %1 mm is outside the widths this machine takes: up to %2 mm</source>
        <translation>A board of %1 mm is outside the widths this machine takes: up to %2 mm</translation>
    </message>
    <message>
        <location line="+3" />
        <source>A drawn profile needs a drawing: import a DXF file</source>
        <translation>A drawn profile needs a drawing: import a DXF file</translation>
    </message>
    <message>
        <location line="+1" />
        <source>A round or oval barrel needs its belly diameter: allowed %1 to %2 mm</source>
        <translation>A round or oval barrel needs its belly diameter: allowed %1 to %2 mm</translation>
    </message>
    <message>
        <location line="+3" />
        <source>An oval barrel needs its short axis</source>
        <translation>An oval barrel needs its short axis</translation>
    </message>
    <message>
        <location line="+1" />
        <source>At %1° a board of %2 mm belongs to a barrel of %3 mm, outside %4 to %5 mm: allowed %6 to %7°</source>
        <translation>At %1° a board of %2 mm belongs to a barrel of %3 mm, outside %4 to %5 mm: allowed %6 to %7°</translation>
    </message>
    <message>
        <location line="+4" />
        <source>At %1° the bevels of a %2 mm thick stave meet before the top face at the %3 mm wide heads: allowed below %4°</source>
        <translation>At %1° the bevels of a %2 mm thick stave meet before the top face at the %3 mm wide heads: allowed below %4°</translation>
    </message>
    <message>
        <location line="+4" />
        <source>No tilt fits a board of %1 mm: no barrel of %2 to %3 mm has such staves</source>
        <translation>No tilt fits a board of %1 mm: no barrel of %2 to %3 mm has such staves</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Only a drawn side profile keeps a drawing</source>
        <translation>Only a drawn side profile keeps a drawing</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The barrel gives a board of %1 mm a tilt of %2°: allowed %3 to %4°</source>
        <translation>The barrel gives a board of %1 mm a tilt of %2°: allowed %3 to %4°</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The drawing's file is not recorded: import the DXF file again</source>
        <translation>The drawing's file is not recorded: import the DXF file again</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The head would be %1 mm wide: allowed %2 mm or more</source>
        <translation>The head would be %1 mm wide: allowed %2 mm or more</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The name contains a control character</source>
        <translation>The name contains a control character</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The name is empty: allowed 1 to %1 characters</source>
        <translation>The name is empty: allowed 1 to %1 characters</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The name must have 1 to %1 characters, with no space at its start or end</source>
        <translation>The name must have 1 to %1 characters, with no space at its start or end</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The note has %1 characters: allowed at most %2</source>
        <translation>The note has %1 characters: allowed at most %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The tool path reaches %1 = %2 %3, beyond the axis travel %4 to %5 %3</source>
        <translation>The tool path reaches %1 = %2 %3, beyond the axis travel %4 to %5 %3</translation>
    </message>
    <message>
        <location line="+3" />
        <source>This side profile has no parameters</source>
        <translation>This side profile has no parameters</translation>
    </message>
    <message>
        <location line="+1" />
        <source>This side profile has no such parameter</source>
        <translation>This side profile has no such parameter</translation>
    </message>
</context>
<context>
    <name>SimPendantPanel</name>
    <message>
        <location filename="../../app/screens/widgets/sim_pendant.py" line="+168" />
        <source>Handwheel and joystick</source>
        <translation>Handwheel and joystick</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Handwheel</source>
        <translation>Handwheel</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Joystick (hold)</source>
        <translation>Joystick (hold)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Off</source>
        <translation>Off</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Hold enable</source>
        <translation>Hold enable</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Leave manual mode</source>
        <translation>Leave manual mode</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Enter manual mode</source>
        <translation>Enter manual mode</translation>
    </message>
</context>
<context>
    <name>States</name>
    <message>
        <location filename="../../app/screens/texts.py" line="+5" />
        <source>STARTING UP</source>
        <translation>STARTING UP</translation>
    </message>
    <message>
        <location line="+1" />
        <source>NOT HOMED</source>
        <translation>NOT HOMED</translation>
    </message>
    <message>
        <location line="+1" />
        <source>HOMING</source>
        <translation>HOMING</translation>
    </message>
    <message>
        <location line="+1" />
        <source>READY</source>
        <translation>READY</translation>
    </message>
    <message>
        <location line="+1" />
        <source>RUNNING</source>
        <translation>RUNNING</translation>
    </message>
    <message>
        <location line="+1" />
        <source>MANUAL</source>
        <translation>MANUAL</translation>
    </message>
    <message>
        <location line="+1" />
        <source>STOPPING</source>
        <translation>STOPPING</translation>
    </message>
    <message>
        <location line="+1" />
        <source>FAULT</source>
        <translation>FAULT</translation>
    </message>
    <message>
        <location line="+1" />
        <source>EMERGENCY STOP</source>
        <translation>EMERGENCY STOP</translation>
    </message>
    <message>
        <location line="+51" />
        <source>NO MACHINE</source>
        <translation>NO MACHINE</translation>
    </message>
</context>
<context>
    <name>StepTimes</name>
    <message>
        <location filename="../../app/screens/widgets/step_times_bar.py" line="+22" />
        <source>Waiting</source>
        <translation>Waiting</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Centering</source>
        <translation>Centering</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Clamping</source>
        <translation>Clamping</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Measuring</source>
        <translation>Measuring</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Spindle</source>
        <translation>Spindle</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Moving clear</source>
        <translation>Moving clear</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Approach</source>
        <translation>Approach</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Side A</source>
        <translation>Side A</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Repositioning</source>
        <translation>Repositioning</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Side B</source>
        <translation>Side B</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Return</source>
        <translation>Return</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Unclamping</source>
        <translation>Unclamping</translation>
    </message>
</context>
<context>
    <name>Steps</name>
    <message>
        <location filename="../../app/screens/texts.py" line="-47" />
        <source>Waiting for a board</source>
        <translation>Waiting for a board</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Centering</source>
        <translation>Centering</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Clamping</source>
        <translation>Clamping</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Measuring the width</source>
        <translation>Measuring the width</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Moving clear of the board</source>
        <translation>Moving clear of the board</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Starting the spindle</source>
        <translation>Starting the spindle</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Cutting side A</source>
        <translation>Cutting side A</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Repositioning and tilting</source>
        <translation>Repositioning and tilting</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Cutting side B</source>
        <translation>Cutting side B</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Returning</source>
        <translation>Returning</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Unclamping</source>
        <translation>Unclamping</translation>
    </message>
</context>
<context>
    <name>SystemScreen</name>
    <message>
        <location filename="../../app/screens/system_screen.py" line="+221" />
        <source>System</source>
        <translation>System</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Home position</source>
        <translation>Home position</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Tool and machine</source>
        <translation>Tool and machine</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Start position P0</source>
        <translation>Start position P0</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Automatic speeds</source>
        <translation>Automatic speeds</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Tool path</source>
        <translation>Tool path</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Axis limits</source>
        <translation>Axis limits</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Jogging</source>
        <translation>Jogging</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Shifts</source>
        <translation>Shifts</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Change log</source>
        <translation>Change log</translation>
    </message>
    <message>
        <location line="+1" />
        <source>OPC UA</source>
        <translation>OPC UA</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+27" />
        <source>Simulation</source>
        <translation>Simulation</translation>
    </message>
    <message>
        <location line="-20" />
        <source>The system settings are locked.
Log in as technician or service to change them.</source>
        <translation>The system settings are locked.
Log in as technician or service to change them.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Unlock with PIN</source>
        <translation>Unlock with PIN</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Lock (log out)</source>
        <translation>Lock (log out)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Change log of the system parameters</source>
        <translation>Change log of the system parameters</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Time</source>
        <translation>Time</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Old</source>
        <translation>Old</translation>
    </message>
    <message>
        <location line="+0" />
        <source>New</source>
        <translation>New</translation>
    </message>
    <message>
        <location line="+0" />
        <source>User</source>
        <translation>User</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Only on the simulated machine: inject a fault to test the alarms, clear the injected faults (the machine stays latched until Reset), put a board in, take it off or replace it, and work the handwheel and the joystick (in manual mode).</source>
        <translation>Only on the simulated machine: inject a fault to test the alarms, clear the injected faults (the machine stays latched until Reset), put a board in, take it off or replace it, and work the handwheel and the joystick (in manual mode).</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Clear injected faults</source>
        <translation>Clear injected faults</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Put a board in</source>
        <translation>Put a board in</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Take the board off</source>
        <translation>Take the board off</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Replace the board</source>
        <translation>Replace the board</translation>
    </message>
    <message>
        <location line="+65" />
        <source>needs %1</source>
        <translation>needs %1</translation>
    </message>
    <message>
        <location line="+8" />
        <source>enforced by the machine, set in its configuration file</source>
        <translation>enforced by the machine, set in its configuration file</translation>
    </message>
    <message>
        <location line="+53" />
        <source>Log in to change parameters.</source>
        <translation>Log in to change parameters.</translation>
    </message>
    <message>
        <location line="+11" />
        <source>%1 set to %2 (logged).</source>
        <translation>%1 set to %2 (logged).</translation>
    </message>
    <message>
        <location line="+30" />
        <source>Fault injected: %1</source>
        <translation>Fault injected: %1</translation>
    </message>
</context>
<context>
    <name>TextKeyboard</name>
    <message>
        <location filename="../../app/screens/widgets/keyboard.py" line="+122" />
        <source>Space</source>
        <translation>Space</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <location line="+1" />
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <location line="+22" />
        <source>At most %1 characters.</source>
        <translation>At most %1 characters.</translation>
    </message>
    <message>
        <location line="+42" />
        <source>Enter a text.</source>
        <translation>Enter a text.</translation>
    </message>
</context>
</TS>

<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
<context>
    <name>QObject</name>
    <message>
        <location filename="../widgets/control_panel.cpp" line="+46"/>
        <source>yes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>no</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>nb::AnalysisWorkspace</name>
    <message>
        <location filename="../widgets/analysis/analysis_workspace.cpp" line="+137"/>
        <source>Runs in the analysis:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Include runs cut short
or without contact</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Runs ended by the force limit, an emergency stop or a fault end where the protection acted, not where the tissue gave way; runs that never touched tissue have nothing to fit. They are left out unless this is on.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Reload labels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+38"/>
        <location line="+490"/>
        <source>Save figure…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-489"/>
        <location line="+490"/>
        <source>Save tables…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-454"/>
        <source>Stiffness</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Tissue:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Friction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+1"/>
        <source>Run:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Validation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+2"/>
        <source>Per run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Pooled per tissue</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Summary</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>By factor</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+227"/>
        <source>%n run(s) analysed</source>
        <translation>
            <numerusform>%n run analysed</numerusform>
            <numerusform>%n runs analysed</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Left out (switch above to include them):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+14"/>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-12"/>
        <source>Outliers:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: C departs from the peak-speed line (Cp %2 %, Cn %3 %); see Friction ▸ Summary</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Fitted, with doubts:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Not fitted:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+25"/>
        <source>made again in the plan: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>left out by default: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+52"/>
        <location line="+15"/>
        <source>cannot create the folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+83"/>
        <source>The factors of a plan&apos;s runs (their factor_… metadata)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Quantity:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>against factor:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+39"/>
        <source>no factor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no fitted quantity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+33"/>
        <location line="+23"/>
        <source>no run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <location line="+10"/>
        <source>Save figure</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-10"/>
        <source>PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Save tables (CSV and LaTeX) into</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Save tables</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>nb::CalibrationWizard</name>
    <message>
        <location filename="../widgets/calibration_wizard.cpp" line="+30"/>
        <source>Calibrate force sensor – %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source> g</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Set masses</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Replaces the table with these masses (individual masses can be edited in the table)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Masses from</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Mass [g]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Voltage [V]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Residual [mV]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Use</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+25"/>
        <location line="+5"/>
        <source>mass [g]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-4"/>
        <source>voltage [V]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>residual [mV]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <location line="+373"/>
        <source>No fit yet: measure at least two masses.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-360"/>
        <source>Measure</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Waits until the reading settles, then averages the sensor voltage over the dwell time for the selected mass</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+73"/>
        <source>Step %1 of %2: the rig hangs %3 g; press Measure.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Step %1 of %2: hang %3 g on the sensor, then press Measure.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>saturated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 g saturates the input (%2 V, the range ends at ±%3 V): the point is refused. Calibrate only up to the masses the sensor can read.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+66"/>
        <source>Discard the %n point(s) measured? They are not saved.</source>
        <translation>
            <numerusform>Discard the %n point measured? It is not saved.</numerusform>
            <numerusform>Discard the %n points measured? They are not saved.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+68"/>
        <source>Step %1 of %2: %3 g – waiting for the reading to settle, then averaging %4 s; keep the mass still…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+83"/>
        <source>All masses measured: check the fit and its residuals, then Save and use.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>All masses measured, but there is no fit yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-305"/>
        <source>Measure all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Measures every row in turn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save and use</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Saves this calibration in the session and uses it for every following run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+334"/>
        <source>d = %1 mV/g,  c = %2 V,  r² = %3,  rms residual = %4 mV,  %5 points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Suspect point: %1 g lies %2× the scatter of the other points off their line. Untick it to leave it out.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>nb::ControlPanel</name>
    <message>
        <location filename="../widgets/control_panel.cpp" line="+23"/>
        <source>EMERGENCY STOP (Esc)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stops the stage at once and ends the run (always available; key: Esc)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>1. Prepare</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Powers the stage drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Takes the present force as zero (needle free of tissue)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Makes the present stage position 0 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Calibrate sensor…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Known masses on the load cell, fit V = d·m + c</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+290"/>
        <source>2. Motion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-287"/>
        <source>Linear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sinusoidal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source> mm/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+14"/>
        <location line="+12"/>
        <location line="+469"/>
        <source> mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-487"/>
        <source>Velocity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Depth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source> Hz</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Amplitude</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frequency</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cycles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+22"/>
        <source>3. Run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+467"/>
        <source>To start (%1 mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-555"/>
        <location line="+445"/>
        <source>&amp;Enable stage</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-442"/>
        <source>&amp;Bias force sensor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Zero position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+56"/>
        <source>The sine oscillates about this depth; the needle moves there first (not recorded)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Centre depth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Start &amp;insertion (moves + records)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Starts recording a new run file, then moves the needle in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Withdraw</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Moves the needle back to 0 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Decelerates the stage; the run keeps recording until End run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Stops recording and closes the run file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Maximum force</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+11"/>
        <source> N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-10"/>
        <source>The stage stops at once when the force reaches this (0 = no limit: runs refused)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Withdrawal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>|F| that stops the needle coming out (never below the maximum force, so a limit stop never traps the needle)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Stage</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Bias done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zero done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Moving</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Force</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Dropped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Recording</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Calibration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Fault</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+236"/>
        <source>The sine would reach %1 mm, past the stage&apos;s travel.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The sine would go above 0 mm: make the centre at least the amplitude.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The depth (%1 mm) is not deeper than the needle is now (%2 mm).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+40"/>
        <location line="+110"/>
        <location line="+9"/>
        <source>Not now: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-112"/>
        <source>Disable stage</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Withdraw (not recorded)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-272"/>
        <location line="+273"/>
        <source>enabled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-273"/>
        <location line="+273"/>
        <source>disabled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-275"/>
        <location line="+276"/>
        <source>yes (%1 V)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-274"/>
        <location line="+276"/>
        <source>at rest</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not recording</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-280"/>
        <location line="+274"/>
        <source>%1 Hz</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 (overruns %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-281"/>
        <location line="+282"/>
        <source>%1 N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-281"/>
        <location line="+282"/>
        <location line="+45"/>
        <source>%1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-326"/>
        <location line="+286"/>
        <source>%1 N (%2 %)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+3"/>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>force limit tripped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&lt;b&gt;EMERGENCY STOP — latched.&lt;/b&gt;&lt;br&gt;The stage is disabled. Check the rig, then reset: this enables the stage again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Reset emergency stop (enable stage)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-293"/>
        <source>Jog (never recorded)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-109"/>
        <location line="+351"/>
        <source>Stop (keeps recording)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-347"/>
        <source>End run (closes file)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Max. force</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+20"/>
        <location line="+425"/>
        <source>To start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-403"/>
        <source>Sampling</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Margin</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Force left before the maximum force stops the stage</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+26"/>
        <location line="+277"/>
        <source>%1 mm/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-257"/>
        <source>Unrecorded moves of the needle: steps in and out, or to a position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+68"/>
        <source>%1 %2 cannot be set here (%3 to %4 in steps of %5)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 cycles cannot be set here (%2 to %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>2. Motion (set by the plan)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+151"/>
        <source>Withdraw (recorded)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+21"/>
        <source>RECORDING %1, %2 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>no limit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+42"/>
        <source>Step of one jog</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>▲ Out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>▼ In</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Go to position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Moves the needle without recording</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Moves the needle out to where the last run began (not recorded)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The needle is not deeper than where the last run began.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>nb::DeviceDialog</name>
    <message>
        <location filename="../widgets/device_dialog.cpp" line="+29"/>
        <source>Devices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>serial number, e.g. 360012345</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Analog input (differential with the next one)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>×1 (±10 V)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>×10 (±1 V)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>×100 (±100 mV)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>×1000 (±10 mV)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>serial port, e.g. /dev/ttyUSB0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The axis&apos;s micro-steps per millimetre (from its data sheet)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Force sensor (DAQ)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+6"/>
        <source>Device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-5"/>
        <source>Serial number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Insertion stage</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Port</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Micro-steps per mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Rescan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Simulated rig</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>LabJack U6, the first found</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Simulated stage</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Zaber on %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>LabJack U6 by serial number…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zaber on another port…</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>Found %n LabJack U6(s)</source>
        <translation>
            <numerusform>Found %n LabJack U6</numerusform>
            <numerusform>Found %n LabJack U6s</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+0"/>
        <source>%n serial port(s)</source>
        <translation>
            <numerusform>%n serial port</numerusform>
            <numerusform>%n serial ports</numerusform>
        </translation>
    </message>
    <message>
        <location line="+55"/>
        <source>Type the U6&apos;s serial number, or choose a listed one.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Type the stage&apos;s serial port (zaber:PORT), or choose a listed one.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>nb::ExportDialog</name>
    <message>
        <location filename="../widgets/export_dialog.cpp" line="+57"/>
        <source>Export session</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Choose…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export into</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>CSV per run, with JSON sidecar and label intervals</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>HDF5: the whole session in one file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ELAN documents (.eaf) linking force and video</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Analysis figures (PNG and PDF)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Analysis tables (CSV and LaTeX)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Export</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Session</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Into folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+76"/>
        <source>Choose a folder to export into.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+28"/>
        <source>%1 already holds an earlier export: %n file(s) will be replaced.</source>
        <translation>
            <numerusform>%1 already holds an earlier export: %n file will be replaced.</numerusform>
            <numerusform>%1 already holds an earlier export: %n files will be replaced.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n file(s) in %1 are not an earlier export&apos;s (a recorded run, a table made by hand?) and would be replaced and lost.</source>
        <translation>
            <numerusform>%n file in %1 is not an earlier export&apos;s (a recorded run, a table made by hand?) and would be replaced and lost.</numerusform>
            <numerusform>%n files in %1 are not an earlier export&apos;s (a recorded run, a table made by hand?) and would be replaced and lost.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Choose another folder unless you are sure.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Replace</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Not exported: the files in %1 are kept.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: cannot create the folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Exporting…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Cancelling…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+47"/>
        <source>%1: no runs to export</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+97"/>
        <source>Cancelled: the earlier export in %1 is as it was.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cancelled: the files finished before (%1) are kept; none is half written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export failed: %1. The earlier export in %2 is as it was.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>Exported %n file(s) into %1</source>
        <translation>
            <numerusform>Exported %n file into %1</numerusform>
            <numerusform>Exported %n files into %1</numerusform>
        </translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Close</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>nb::ForcePlots</name>
    <message>
        <location filename="../widgets/force_plots.cpp" line="+61"/>
        <location line="+1"/>
        <source>time [s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-1"/>
        <location line="+2"/>
        <source>force [N]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-1"/>
        <location line="+1"/>
        <source>position [mm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>force</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>force vs position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Follow</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Keep the newest samples in view (zooming or dragging a plot turns this off)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Pause display</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Freeze the plots to look closely; recording goes on and nothing is lost</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Show whole run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zoom out to every sample of the run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+90"/>
        <source>contact</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>puncture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>withdraw</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>E-STOP</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fault</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>force limit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+165"/>
        <source>limit %1 N%2 · margin %3 N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source> (above the plot)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>nb::LabelModel</name>
    <message>
        <location filename="../widgets/label_model.cpp" line="+90"/>
        <source>track</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>label</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>start [s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>end [s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>comment</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>nb::LabelSetDialog</name>
    <message>
        <location filename="../widgets/label_set_dialog.cpp" line="+23"/>
        <source>Label set: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>track</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>label</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>kind</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>hotkey</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Add label</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>new label</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Remove label</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Renaming a label does not rename the labels already placed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <source>interval</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+24"/>
        <source>one frame back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>one frame forward</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>play / pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>split</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>delete</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Row %1: a label needs a track and a name.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: the hotkey must be one key without Ctrl, Shift or Alt.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: the key %2 already means “%3” in the review workspace.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 is in the set twice.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The key %1 is given to both %2/%3 and %4.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>nb::MainWindow</name>
    <message>
        <location filename="../app/main_window.cpp" line="+71"/>
        <source>NeedleBench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <source>&amp;Record</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Analysis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Control panel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Session</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Could not open the configured devices (%1); using the simulated rig.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/main_window_safety.cpp" line="+49"/>
        <source>Emergency stop reset: the stage is enabled again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Withdrawing to the start position, %1 mm (not recorded)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+49"/>
        <source>Emergency stop: the stage is disabled until you reset it in the control panel.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="+591"/>
        <location filename="../app/main_window_safety.cpp" line="+15"/>
        <location line="+31"/>
        <location line="+19"/>
        <source>Not now: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/main_window_safety.cpp" line="-37"/>
        <source>Do it anyway only if you are sure the needle is free and at rest.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Bias force sensor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Bias &amp;anyway</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Bias taken under load on purpose: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Bias not taken: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Zero position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Zero &amp;anyway</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Position zeroed in tissue on purpose: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Position not zeroed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Simulated rig of this session: %1, seed %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Simulated rig: %1, seed %2, %3 Hz</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="-484"/>
        <source>Recording %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Run not started</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Fault: %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Force limit tripped at %1 N, %2 mm: the stage was stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Devices not changed: close the calibration wizard first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Could not open the chosen devices (%1); using the simulated rig.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Devices: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>&amp;Session</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;New session…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Open session…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Session &amp;details…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Devices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Choose devices…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Simulated rig…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Calibration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Calibrate force sensor…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Use the sensor&apos;s &amp;nominal calibration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>These devices do not state a nominal calibration: calibrate the sensor.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The language changes when NeedleBench is started again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Interrupted runs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-3"/>
        <source>Could not recover:
%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="-4"/>
        <source>Recovered %n interrupted run(s): %1. Each ends where its recording stopped; its file says &apos;end_reason: recovered&apos;.</source>
        <translation>
            <numerusform>Recovered %n interrupted run: %1. It ends where its recording stopped; its file says &apos;end_reason: recovered&apos;.</numerusform>
            <numerusform>Recovered %n interrupted runs: %1. Each ends where its recording stopped; its file says &apos;end_reason: recovered&apos;.</numerusform>
        </translation>
    </message>
    <message>
        <location line="-17"/>
        <location line="+30"/>
        <source>Open session</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-29"/>
        <source>%1 is open in another NeedleBench (%2). Close it there first, or open another session.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Session %1 open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>NeedleBench – %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+26"/>
        <source>New session</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+21"/>
        <source>The last session, %1, is not there any more (moved or renamed?): open it where it is now, or start a new one.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>No session open: start a new one or open one (Session menu).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+30"/>
        <source>The run in review when NeedleBench closed is gone: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Open &amp;video for the run in review…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Export session…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Open a session to export it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Session exported into %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export not finished: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+53"/>
        <source>Session details</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Session details saved; the next runs carry them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Open session folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+44"/>
        <source>Calibration %1 saved in the session and used for every following run (d = %2 mV/g, r² = %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Calibration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+63"/>
        <source>Nothing moves or records now. Quit?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Run saved: %1 (%2, %3 samples, %4 dropped)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Run stopped, file incomplete: %1 (%2, %3 samples, %4 dropped)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Run file incomplete</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 could not be written to the end, and the stage was stopped: %2

The rows written before are kept in the file. Free space on the disk (or choose another session folder) before the next run.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Could not read the run back to mark its events: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+74"/>
        <source>%1
Stop the stage now (emergency stop; the run is saved as such) and quit?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1
Stop the stage now (emergency stop) and quit?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The needle is still in the tissue. Withdraw it first, or quit and leave it there?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The needle is %1 mm from its start. Withdraw it first, or quit and leave it there?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A force of %1 N is on the needle: it may be in the tissue. Withdraw it first, or quit and leave it there?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Don&apos;t quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-835"/>
        <source>Revie&amp;w</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+661"/>
        <source>%1 · %2 Hz · %3 samples · dropped %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+13"/>
        <source>%1
%n plot frame(s) drawn</source>
        <translation>
            <numerusform>%1
%n plot frame drawn</numerusform>
            <numerusform>%1
%n plot frames drawn</numerusform>
        </translation>
    </message>
    <message>
        <location line="+157"/>
        <location line="+3"/>
        <source>Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-598"/>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/main_window_plan.cpp" line="+38"/>
        <source>pending</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>again: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>again (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>skipped: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>redone</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>sine ±%1 mm at %2 Hz, %3 cycles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>linear to %1 mm at %2 mm/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>seed %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>stop at the first puncture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>stop after %1 punctures</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>slow to %1 mm/s after a puncture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>force limit %1 N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 (from the template %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Plan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Plan run %1 skipped: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Plan run %1 is made again: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Left the plan: the control panel is yours; runs made now are not the plan&apos;s.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>New &amp;plan from template…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open plan &amp;file…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+7"/>
        <source>Open plan file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-7"/>
        <source>Plans (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Open a session first: the plan is kept in it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>New plan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Experiment plan</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>Plan &quot;%1&quot;: %n run(s), kept in %2</source>
        <translation>
            <numerusform>Plan &quot;%1&quot;: %n run, kept in %2</numerusform>
            <numerusform>Plan &quot;%1&quot;: %n runs, kept in %2</numerusform>
        </translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The session&apos;s plan could not be opened: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Set by plan run %1 (%2); Leave plan in the Plan dock frees it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Plan run %1 cannot be set: %2. Left the plan.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Plan run %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Simulated rig for plan run %1: %2, seed %3 (enable, bias and zero again)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Run %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1. %2 – %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>run %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Plan run %1 could not be recorded in plan.json: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>nb::NewPlanDialog</name>
    <message>
        <location filename="../widgets/plan_panel.cpp" line="+211"/>
        <source>New plan from template</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>as listed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>randomised</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>blocked by site</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Recorded in the plan: the same seed gives the same order</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Template</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Order</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Seed</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>nb::PlanPanel</name>
    <message>
        <location line="-206"/>
        <source>No experiment plan in this session. Session ▸ New plan from template… makes one; its runs are then set here one after the other.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>New plan from template…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+36"/>
        <source>Bias done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ticks itself when the sensor has been biased since the last run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zero done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ticks itself when the position has been zeroed since the last run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Done:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Skip run…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Marks the next run skipped, with a reason, and moves on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Redo run…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Skip run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Why is %1 skipped?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Redo run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Why is %1 made again? Its attempt stays in the plan, marked discarded.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Every run of the plan is completed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Next: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>No run of the plan is done yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Makes %1 again, with a reason</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Leave plan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Return to plan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Releases the control panel&apos;s settings; runs made meanwhile are not the plan&apos;s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sets and locks the next plan run&apos;s settings again</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>nb::PlanReasonDialog</name>
    <message>
        <location line="+36"/>
        <source>e.g. a vessel at this site</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>nb::PlanWalker</name>
    <message>
        <location filename="../app/plan_walker.cpp" line="+27"/>
        <source>Plan run %1 had ended before the interruption (%2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Plan run %1 was interrupted; it runs again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Open a session first: the plan is kept in it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+196"/>
        <location line="+27"/>
        <source>A plan run is recording: end it first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-216"/>
        <source>%1 already holds the plan &quot;%2&quot; with runs made; use another session for a new plan.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+117"/>
        <source>the operator&apos;s step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bias</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>zero</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Plan run %1: tick the checklist first (%2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>No plan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>All %1 runs completed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>less than a minute left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>about %1 min left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run %1 of %2 · %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+44"/>
        <source>No plan run is next.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+27"/>
        <source>Give a reason.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>nb::ReviewWorkspace</name>
    <message>
        <location filename="../widgets/review_workspace.cpp" line="+101"/>
        <source>Indexing the video: %1 of %2 frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Indexing the video: %1 frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+738"/>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-709"/>
        <source>%1 (not attached: the run keeps the video it had)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>decoded across a damaged stretch: partly made up by the decoder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1135"/>
        <source>Low confidence: the video&apos;s coder shows this slow needle late, by %1 ms give or take %2 ms; check the offset on an event (contact or puncture) before accepting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Low confidence: if the needle is faint or burnt-in text lies on its line, draw the line on the video with Shift+drag (shaft to tip) and a region around its path with a drag, then Auto sync again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-1103"/>
        <source>Automatic sync failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Suggestion stopped: the run or its video changed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Suggestion dropped: the video&apos;s offset changed while it was read; suggest again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>force and position only (%1: %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>force, position and the tissue&apos;s motion in %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>force and position; no relaxation from %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>force and position, the relaxation from the surface in %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+37"/>
        <source>recording time [s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>force [N]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>force</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>recorded position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+1168"/>
        <source>needle tracked in the video</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-1165"/>
        <source>position [mm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+44"/>
        <source>−10</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>ten frames back (Shift+Left)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>−1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>one frame back (Left)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+631"/>
        <source>Play</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-631"/>
        <source>play / pause (Space)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>+1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>one frame forward (Right)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>+10</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>ten frames forward (Shift+Right)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1×</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+25"/>
        <source> s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-24"/>
        <source>jump to a recording time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>go to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>video offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>video time = recording time + offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>set the video offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source> ppm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>clock drift of the video against the force record (video runs fast: positive)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>set the drift</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>drift</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>−1 frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+7"/>
        <source>nudge the offset by one frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-2"/>
        <location line="+7"/>
        <source>nudge the offset by a frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-5"/>
        <source>+1 frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Mark event in force</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>the event is at the cursor in the force record</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mark event in video</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>the event is in the frame shown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+956"/>
        <source>Auto sync</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-944"/>
        <source>coded once</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>tick when the video is as its camera or console wrote it, never converted (as a lab converts a console&apos;s export to H.264): the coder&apos;s lag on a slow needle, and the offset with it, are then known more closely. Kept with the run&apos;s video.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+200"/>
        <source>the labels file could not be copied aside: the next label saved replaces it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the labels file as it was is kept in %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+21"/>
        <source>labels taken from %1 (not yet saved beside the run)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>labels kept in %1 are saved beside the run again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>labels kept in %1 cannot be read: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 opened: %2 samples, %3 labels read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+311"/>
        <source>The cursor (%1 s) is outside the recording (%2 to %3 s): labels and force marks go on the recording</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+48"/>
        <source>set the offset and drift from two events</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>set the offset from an event</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+99"/>
        <source>Redone: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Undone: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+71"/>
        <source>They are kept in %1, and saved beside the run when it is opened again and its folder can be written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+88"/>
        <source>Low confidence: the video&apos;s coder shows this slow needle late, by %1 ms give or take %2 ms, as it may have been converted; if it is as the camera or console coded it, tick “coded once”, else check the offset on an event (contact or puncture) before accepting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Kept with the video: Auto sync now fits the offset for it at once</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Sync fitted again for a video coded once: confidence %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Sync fitted again for a video that may have been converted: confidence %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+38"/>
        <source>Automatic sync stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Stop sync</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stop the automatic sync (the offset in use stays)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>track the needle and fit its displacement to the recorded position. Drag on the video to draw a region: the needle is read in it alone (leave burnt-in clocks and counters out). Shift+drag from the shaft to the tip to draw the needle&apos;s line where it is not found.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+69"/>
        <source>needle tracked (offset found)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+59"/>
        <source>accept the sync found</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-1058"/>
        <source>r: correlation of the needle&apos;s tracked displacement with the recorded position at the offset found; confidence also weighs how unique the peak is, whether both halves of the video agree and the motion onsets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+33"/>
        <source>phases or events from force and position, and from the synchronised video when there is one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+227"/>
        <source>No run open: double-click one in the session list</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+27"/>
        <source>labels: %n</source>
        <translation>
            <numerusform>labels: %n</numerusform>
            <numerusform>labels: %n</numerusform>
        </translation>
    </message>
    <message>
        <location line="+36"/>
        <location line="+22"/>
        <source>Open a run first (double-click it in the session list), then attach its video</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-18"/>
        <source>%1: no such video file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 attached to %2; sync it (Auto sync, or mark an event in both)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Open the video of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Video not attached: %1 is no longer the run in review</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+27"/>
        <source>The video of this run, %1, is missing. Open it again where it now lies.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+41"/>
        <source>Video and sync not kept: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+230"/>
        <source>%1 on %2 closed at %3 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 on %2 was not closed (it would be empty or overlap another phase): not added</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+106"/>
        <source>They could not be kept elsewhere either (%1): they are lost when another run is opened.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Labels not saved</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Labels not saved: %1

%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>force and position (synchronise the video to have its motion used)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>force and position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>force and position (the video is still being indexed)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Reading the motion in %1 for the suggestion…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Reading the motion in %1 for the suggestion: frame %2 of %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+22"/>
        <source>%n label(s) suggested from %1: check and correct them</source>
        <translation>
            <numerusform>%n label suggested from %1: check and correct them</numerusform>
            <numerusform>%n labels suggested from %1: check and correct them</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>(%n more left out: they overlap labels already there)</source>
        <translation>
            <numerusform>(%n more left out: it overlaps labels already there)</numerusform>
            <numerusform>(%n more left out: they overlap labels already there)</numerusform>
        </translation>
    </message>
    <message>
        <location line="+130"/>
        <source>correlating: frame %1 of %2…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+72"/>
        <source>, drift %1 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>, coded pictures %1 ms late (allowed for)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>LOW CONFIDENCE: %1; check it on an event before accepting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-1026"/>
        <source>Accept</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>use the offset found</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>accept a low confidence</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the offset found is below the accept threshold: tick only after checking it on an event in both</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Reject</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>keep the current offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>video offset [s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Suggest labels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Edit label set…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>add, rename or remove the labels of this protocol and their hotkeys</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+62"/>
        <source>Keys: %1 · S split · Del delete · Ctrl+Z undo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Label set of %1 saved: %2 labels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+165"/>
        <source>Indexing the video…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+72"/>
        <source>Videos (%1);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+158"/>
        <source>Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+40"/>
        <source>Event marked in the force record at %1 s; now step the video to it and mark it there</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Event marked in the video at %1 s; now mark it in the force record</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Offset and drift set from two events (%1 s apart): drift %2 ppm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Offset set. With the event before, it would mean a drift of %1 ppm, which no clock has: check both marks; the drift was kept</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Offset set; mark a second event, a second or more away, in both to set the drift too</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+74"/>
        <source>%1 overlaps another phase on %2: not added</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+95"/>
        <source>Labels not saved: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+50"/>
        <source>suggest labels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+72"/>
        <source>Open a run and a video first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>correlating…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+120"/>
        <source>found %1 s (confidence %2, r = %3)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>nb::RunListModel</name>
    <message>
        <location filename="../widgets/session_view.cpp" line="+42"/>
        <source>recording</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+35"/>
        <source>#</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Motion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>State</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Calibration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Saved</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>nb::SessionInfoDialog</name>
    <message>
        <location filename="../widgets/session_info_dialog.cpp" line="+22"/>
        <source>New session</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Session details</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source> mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Slab thickness on the friction platform; 0 for a whole organ</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>overall stiffness, friction, …</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Organ</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Specimen number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Needle tip</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Thickness</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Operator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Protocol</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Notes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Browse…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+8"/>
        <source>Parent folder</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>nb::SessionView</name>
    <message>
        <location filename="../widgets/session_view.cpp" line="+75"/>
        <source>No session open (Session ▸ New or Open).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>specimen %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-13"/>
        <source>%1 tip</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-5"/>
        <source>beveled tip</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>diamond tip</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>blunt tip</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 mm thick</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>operator %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&lt;b&gt;%1&lt;/b&gt; – %2&lt;br&gt;active calibration: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no specimen details</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>none saved in this session (the sensor&apos;s nominal one is used)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>nb::SimulatedRigDialog</name>
    <message>
        <location filename="../widgets/simulated_rig_dialog.cpp" line="+19"/>
        <source>Simulated rig</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the preset&apos;s usual tip</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source> Hz</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Tissue preset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Needle tip</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Random seed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sample rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The rig is rebuilt when you press OK; each run&apos;s file records these settings.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>nb::TrCli</name>
    <message>
        <location filename="../app/cmd_acquire.cpp" line="+27"/>
        <source>sim | u6 | u6:SERIAL (default: settings, else sim)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sim | zaber:PORT (default: settings, else sim)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stiffness|internal|friction|prostate (friction: sine motion)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../app/cmd_simulate.cpp" line="+49"/>
        <source>the run file to write</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../app/cmd_simulate.cpp" line="-11"/>
        <source>sampling rate, 100..10000 (default 500)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>insertion velocity (default 4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../app/cmd_simulate.cpp" line="+2"/>
        <source>insertion depth from the start position (default 40)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sine amplitude (default 10)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../app/cmd_simulate.cpp" line="+2"/>
        <source>sine frequency (default 0.5)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../app/cmd_simulate.cpp" line="+1"/>
        <source>sine cycles (default 7)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../app/cmd_simulate.cpp" line="+3"/>
        <source>force limit that stops the stage (default 8)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stage resolution (default: settings, else 20997.375)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sensor calibration slope d in V/g (default: settings, else nominal)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../app/cmd_simulate.cpp" line="+5"/>
        <source>stop the insertion at a puncture: puncture (the first) or puncture:N (the N-th)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../app/cmd_simulate.cpp" line="+1"/>
        <source>slow the insertion to V mm/s after the first puncture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>replace an existing run file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Run &apos;needlebench acquire --help&apos; for the options.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>--protocol must be one of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../app/cmd_simulate.cpp" line="+39"/>
        <source>--out RUN.csv is required</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>--%1 must be a number in [%2, %3] (got &apos;%4&apos;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+57"/>
        <location filename="../app/cmd_simulate.cpp" line="+129"/>
        <source>--stop-at wants puncture or puncture:N with N ≥ 1 (got &apos;%1&apos;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/interrupt_watcher.cpp" line="+112"/>
        <source>%1 received: stopping the stage and closing the run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cmd_acquire.cpp" line="+27"/>
        <location filename="../app/cmd_simulate.cpp" line="+102"/>
        <source>recording failed: %1; the run file keeps %2 whole rows</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cmd_devices.cpp" line="+17"/>
        <location filename="../app/cmd_events.cpp" line="+47"/>
        <location filename="../app/cmd_fit.cpp" line="+141"/>
        <location line="+49"/>
        <location line="+150"/>
        <location filename="../app/cmd_plan.cpp" line="+78"/>
        <location line="+169"/>
        <location line="+295"/>
        <location filename="../app/cmd_sync.cpp" line="+42"/>
        <location filename="../app/cmd_video.cpp" line="+50"/>
        <location line="+36"/>
        <source>print JSON</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <location line="+7"/>
        <source>simulated load cell (default)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-5"/>
        <location line="+11"/>
        <source>simulated stage (default)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-7"/>
        <source>DAQs (--daq):
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Stages (--stage):
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cmd_events.cpp" line="+2"/>
        <source>a constant-velocity insertion run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <location filename="../app/cmd_fit.cpp" line="-302"/>
        <location line="+20"/>
        <location filename="../app/cmd_labels.cpp" line="+118"/>
        <location filename="../app/cmd_sync.cpp" line="+66"/>
        <source>warning: %1
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+35"/>
        <source>events of %1 (force zeroed by %2 N, noise %3 N)
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>event                 time_s position_mm   force_N
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>contact</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>puncture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>relaxation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>internal puncture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>puncture depth %1 mm; stiffness a1 = %2 N/mm, a2 = %3 N/mm² (as fit stiffness gives it)
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>puncture depth %1 mm; no stiffness fit (%2)
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cmd_export.cpp" line="+54"/>
        <source>warning: %1: could not copy the video beside the export; linked where it is</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Export a session&apos;s runs, labels and metadata.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../app/cmd_plan.cpp" line="+8"/>
        <source>a session folder (or any folder of run files)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>csv: a CSV + JSON sidecar + label interval table per run (OUT is a folder); hdf5: one HDF5 file (OUT is the file); eaf: an ELAN document per run with its force CSV linked (OUT is a folder)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>where to write</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>put each run&apos;s video beside the export (hard link, else copy) and link that, so the export folder can be moved or shared on its own</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>replace files in OUT that are not an earlier export&apos;s (a run file, a table made by hand); an earlier export&apos;s files are replaced without it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>--format is required (csv|hdf5|eaf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>unknown format &apos;%1&apos; (csv|hdf5|eaf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+5"/>
        <source>Run &apos;needlebench export --help&apos; for the options.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-1"/>
        <source>--out PATH is required</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>--out %1 is the session folder itself; its run files would be replaced. Name another folder.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--out %1 exists and is not an HDF5 file (a run file?); it is kept. Name another file.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+80"/>
        <source>the %n file(s) this export had written are removed</source>
        <translation>
            <numerusform>the %n file this export had written is removed</numerusform>
            <numerusform>the %n files this export had written are removed</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+79"/>
        <source>%n run(s) of the session left out (named above): %1</source>
        <translation>
            <numerusform>%n run of the session left out (named above): %1</numerusform>
            <numerusform>%n runs of the session left out (named above): %1</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/cmd_demo.cpp" line="+59"/>
        <source>Simulate, label, fit and export a short session in one go.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the folder to write everything into</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a shorter session (one run per condition, fewer cycles)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>--out DIR is required</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Run &apos;needlebench demo --help&apos; for the options.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+41"/>
        <source>session folder %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+48"/>
        <source>simulating %1 failed: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>simulated %1 (%2, %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>sine %1 Hz</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>insertion 4 mm/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>rendered imaging video %1 (%2 frames at 29.97/s, started %3 s before the recording)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+22"/>
        <source>synchronised %1: offset %2 s found, %3 s true (%4 frames off), confidence %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>note: could not synchronise %1 (%2); its frames are numbered without an offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+20"/>
        <source>phases a, b1, b2, c per half-cycle, checked against the tissue&apos;s motion in %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>phases a, b1, b2, c per half-cycle from force and position (%1: %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>contact and puncture events; no imaging video to read the relaxation off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>labelled %1: %2 suggested labels (%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-10"/>
        <source>phases a, b1, b2, c per half-cycle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-150"/>
        <source>%1 is not empty; a demo writes a session and its exports into --out: choose an empty or new folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+165"/>
        <location line="+4"/>
        <location filename="../app/cmd_export.cpp" line="-144"/>
        <source>warning: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fitted %1 stiffness runs in %2 groups, %3 friction runs, %4 validations</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>wrote %1 run CSVs with JSON sidecars and label interval tables</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>wrote %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>wrote %1 fit tables (CSV and LaTeX)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+26"/>
        <source>wrote %1 figures</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Demo finished in %1 s. Where everything went:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>  session (run files + labels): %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>  run CSVs + JSON sidecars:     %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>  HDF5 (all runs):              %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>  fit tables (CSV, LaTeX):      %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>  figures (PNG, PDF, SVG):      %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>  simulator ground truth:       %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>  video %1 (%2 frames): sync offset %3 s found, %4 s true, %5 ms off, confidence %6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>  video %1 (%2 frames): not synchronised (%3); true offset %4 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>  stiffness %1: a1 = %2 N/mm, a2 = %3 N/mm², puncture at %4 mm, %5 N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>  friction overall: Cp = %1 N/m, Cn = %2 N/m, bp = %3 N s/m², bn = %4 N s/m²</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cmd_export.cpp" line="+2"/>
        <source>%1: no run files (*.csv with time_s,position_mm,force_N)</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+13"/>
        <source>%n file(s) in %1 would be replaced that are not an earlier export&apos;s (%2); they are kept. Name another folder, or give --overwrite.</source>
        <translation>
            <numerusform>%n file in %1 would be replaced that is not an earlier export&apos;s (%2); it is kept. Name another folder, or give --overwrite.</numerusform>
            <numerusform>%n files in %1 would be replaced that are not an earlier export&apos;s (%2); they are kept. Name another folder, or give --overwrite.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+7"/>
        <source>note: replacing %n file(s) of an earlier export in %1</source>
        <translation>
            <numerusform>note: replacing %n file of an earlier export in %1</numerusform>
            <numerusform>note: replacing %n files of an earlier export in %1</numerusform>
        </translation>
    </message>
    <message>
        <location line="+33"/>
        <source>the earlier export in %1 is as it was</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>warning: removed %1, left by an export that did not finish</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>writing %1 runs to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>cancelled; %1 was not written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cmd_demo.cpp" line="-254"/>
        <location filename="../app/cmd_export.cpp" line="-23"/>
        <location line="+11"/>
        <location line="+19"/>
        <source>%1: cannot create the folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cmd_export.cpp" line="+10"/>
        <source>cancelled after %1 of %2 runs; %3 was not written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+21"/>
        <source>exported %1 runs from %2 as %3: %4 files</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cmd_fit.cpp" line="+2"/>
        <source>warning: %1: %2
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>warning: %1: %2 not used by this fit (it reads %3)
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>warning: %1 is given more than once; it is fitted once</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+34"/>
        <source>%1: the fit gave no finite result (forces or positions out of any measurable range?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+27"/>
        <source>calibration points: columns mass_g, voltage_V</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+24"/>
        <source>calibration %1: V = %2 V/g * m + %3 V   r2 = %4   rms = %5 V
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>    mass_g   voltage_V  residual_V
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>  &lt;- largest residual, check this point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>a run&apos;s labels (track,label,start_s,end_s,comment); its &apos;contact&apos; and &apos;puncture&apos; points replace the detected ones. Give it once per run, in the runs&apos; order.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>constant-velocity insertion runs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 label files for %2 runs; give --labels once per run, in the runs&apos; order
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Usage: needlebench fit stiffness RUN.csv... [--labels FILE]... [--json]
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+24"/>
        <source>warning: %1 marks no %2 for %3: found in the force instead</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source> or </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+51"/>
        <source>stiffness f = a1*x + a2*x^2, x = depth past contact [mm]
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>run                       contact_mm puncture_mm depth_mm  force_N  a1_N/mm   a2_N/mm2  rms_N    r2
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>pooled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mean of runs: a1 = %1 ± %2 N/mm, a2 = %3 ± %4 N/mm²
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>alternatives (pooled): cubic rms %1 N r2 %2 (a3 = %3 N/mm³); spring x/(a x + b) rms %4 N r2 %5
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+39"/>
        <source>length of needle in tissue (slab thickness), required</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>needle holder mass removed from the force (eq. 21, default 0.087)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>estimate the mass with the friction (eq. 19)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>zero-velocity band width, e.g. 0.005 = ±2.5 mm/s (default: found in each run&apos;s data)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>phase labels (track,label,start_s,end_s,comment) for a single run; C and b then come from phase c, D from phase a. Runs may carry a &apos;phase&apos; column instead. Without phases the velocity band decides.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the tissue&apos;s velocity over the run (time_s,tissue_velocity_mm_s, as labels suggest --tissue-trace writes it from the video) for a single run: C and b are then fitted against the needle&apos;s velocity relative to the tissue</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>sinusoidal runs through a tissue slab</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>--thickness-mm is required</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>--thickness-mm: %1 mm is no slab (at most %2 mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>--thickness-mm: &apos;%1&apos; is not a positive number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>--mass-kg and --estimate-mass exclude each other</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--mass-kg: &apos;%1&apos; is not a mass</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--band-m-s: &apos;%1&apos; is not a positive number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>--labels applies to a single run; give one run per call</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+24"/>
        <source>warning: %1 holds no friction phase over %2 (a, b1, b2, c); the run&apos;s own phase column is used, else the velocity band</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+149"/>
        <source>friction per unit length of needle in tissue (thickness %1 mm): C, D in N/m, b in N·s/m²
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>group             statistic freq_Hz </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>  m_est_kg </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>       Cp        Bp        Cn        Bn        Dp        Dn
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>no result</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+38"/>
        <source>%1: standard errors of D per length: Dp ±%2, Dn ±%3 (the spread of %4 and %5 break-aways)
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>above %1 mm/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>not seen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: the tissue was still arriving at the plate as the needle passed its top speed (+ motion: %2, - motion: %3); those samples are left out of the sliding line and the peak point
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>+ motion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>- motion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: in %2 the slab gives against the plate by %3 N/m up to %4 N (read where the needle carries it in, %5 times); C and b are taken against the tissue&apos;s motion where it rests on that give
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: NOT A RESULT (not physical, or not determined by this run): %2
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-60"/>
        <location filename="../app/cmd_plan.cpp" line="-29"/>
        <source>run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-227"/>
        <source>Usage: needlebench fit friction RUN.csv... --thickness-mm T [--mass-kg M | --estimate-mass] [--band-m-s B] [--labels FILE] [--tissue-trace FILE.csv] [--json]
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+35"/>
        <source>--tissue-trace applies to a single run; give one run per call</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+195"/>
        <source>%1Hz (%2 runs)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+3"/>
        <source>mean</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-2"/>
        <location line="+3"/>
        <source>std</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-1"/>
        <location line="+1"/>
        <source>all (%1 runs)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>peak speeds</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: D from %2, rms %3 N
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: zero-velocity band found in the data: ±%2 mm/s after turning points, ±%3 mm/s before them
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: zero-velocity band ±%2 mm/s (given)
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: C and b fitted against the needle&apos;s velocity relative to the tissue&apos;s (%2)
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: standard errors per length: Cp ±%2, bp ±%3, Cn ±%4, bn ±%5
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 N/m</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>no give seen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: the slab springs back off the plate as the needle slows (its stiffness against the plate: %2 in + motion, %3 in - motion); C and b are taken against the tissue&apos;s motion
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1: C departs from the peak-speed line (Cp %2 %, Cn %3 %): the tissue moves while the needle slows, so this run&apos;s sliding line is tilted; prefer the peak-speed line
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>peak-speed line: C and b through the top speeds of %1 runs (%2 to %3 mm/s), where the needle does not accelerate and the tissue rests against the plate; standard errors per length: Cp ±%4, bp ±%5, Cn ±%6, bn ±%7
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>no peak-speed line: it needs three runs or more whose tissue settled at the top and whose top speeds differ by a fifth or more (e.g. the same slab at 0.2, 0.5 and 0.8 Hz)
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Usage: needlebench fit calibration FILE.csv [--json]
       needlebench fit stiffness RUN.csv... [--json]
       needlebench fit friction RUN.csv... --thickness-mm T [--mass-kg M | --estimate-mass]
                                [--band-m-s B] [--labels FILE] [--json]
&apos;needlebench fit WHAT --help&apos; describes each.
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+30"/>
        <source>needlebench fit: say what to fit
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>needlebench fit: unknown fit &apos;%1&apos;
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cmd_labels.cpp" line="-83"/>
        <source>Labels of a run. Actions: suggest (phases or events from the data).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>suggest</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../app/cmd_sync.cpp" line="-78"/>
        <source>the run file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>labels file to write (default RUN.labels.csv)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>print the labels as JSON</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>video time at the recording&apos;s start (default: the run&apos;s stored sync, else found automatically)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the video clock&apos;s rate error, e.g. 0.001 (default 0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>write the tissue&apos;s velocity read off the video as CSV (time_s,tissue_velocity_mm_s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>needlebench labels: unknown action &apos;%1&apos; (suggest)

</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <location line="+6"/>
        <source>the labels file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1: a folder, not a video</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: no such video</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>needlebench labels: --video-offset-s wants seconds and --video-drift a rate error below 0.1
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: too few samples (%2) to suggest labels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>needlebench labels: the run&apos;s video %1 is missing; looking beside the run
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>needlebench labels: no video for %1 (none linked, none beside it): --video-offset-s and --video-drift are not used
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+43"/>
        <source>needlebench labels: %1: the surface&apos;s motion could not be read (%2); no relaxation suggested
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-1"/>
        <source>needlebench labels: %1: the tissue&apos;s motion could not be read (%2); phases from force and position only
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-146"/>
        <source>the run&apos;s imaging video: friction phases also from the tissue&apos;s motion in it, the relaxation of insertion runs from the surface&apos;s spring-back (default: the video linked to the run, else RUN.mp4, RUN.avi… beside it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>replace an existing labels file (it may hold labels made by hand), and let --tissue-trace replace a file that is not a trace</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+140"/>
        <source>needlebench labels: %1: no relaxation suggested: %2
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+25"/>
        <source>%1 labels suggested, written to %2
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cmd_simulate.cpp" line="-288"/>
        <source>stiffness|internal|friction|prostate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>liver1|liver2|liver3|liver5|liver7|prostate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>beveled|diamond|blunt</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>random seed (default 1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>insertion velocity (default 4, internal 2.5)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>sine amplitude, at most the stage&apos;s 10 mm travel (default 10)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>tissue slab thickness on the friction platform (default 30)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bone this far below the surface (very stiff)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>run on the wall clock (default: as fast as possible)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>write the ground truth as JSON</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>also render the imaging view (29.97 frames/s; .avi, .mkv or .mp4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>friction platform: the tissue sticks while the relative velocity is within ±V (default 2.5)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>friction platform: free travel of the slab before it meets a plate (default 1.5)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rms noise of the force sensor in newtons (default about 0.0012)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>replace existing output files (--out, --truth, --video)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>--%1: &apos;%2&apos; is not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>--protocol is required (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown protocol &apos;%1&apos; (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <source>--truth and --out name the same file %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>--video names the same file as --out or --truth: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <location filename="../app/plan_runner.cpp" line="+109"/>
        <source>unknown tissue &apos;%1&apos; (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <location filename="../app/plan_runner.cpp" line="+6"/>
        <source>unknown tip &apos;%1&apos; (beveled|diamond|blunt)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>--seed: &apos;%1&apos; is not a non-negative integer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>--rate-hz must be between 100 and 10000 (got %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--velocity-mm-s must be in (0, %1]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--depth-mm must be in (0, %1]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>--amplitude-mm must be in (0, %1]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>--frequency-hz must be in [0.01, 5]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--thickness-mm must be in (0, %1]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--cycles must be a whole number in [1, 1000]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+27"/>
        <source>--bone-depth-mm must be in (0, %1]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+111"/>
        <source>the run did not end by itself: no truth or video is written for it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-269"/>
        <source>the video starts this long before the recording; negative: after it began (-600 to 600, default 0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+61"/>
        <source>--video-offset-s wants seconds between -600 and 600</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+67"/>
        <source>--max-force-n must be in [0.01, 100]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>--stick-band-mm-s must be in (0, 50]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>--plate-gap-mm must be in [0, 20]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--force-noise-n must be in [0, 1]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+22"/>
        <source>--slow-after-puncture must be in (0, %1] mm/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+25"/>
        <source>warning: the disk holding %1 will be full in about %2 s at the current rate (%3 kB free)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Run &apos;needlebench simulate --help&apos; for the options.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cmd_plan.cpp" line="-480"/>
        <source>Run &apos;needlebench plan %1 --help&apos; for the options.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Usage: needlebench plan templates [--json]
       needlebench plan new --template NAME --out PLAN.json [--order listed|random|blocked] [--seed N]
                            [--set KEY=VALUE]... [--levels FACTOR=L1,L2,...]...
       needlebench plan show PLAN.json [--json]
       needlebench plan run PLAN.json --session DIR [--daq DAQ --stage STAGE] [--yes]
       needlebench plan skip PLAN.json --run N --reason TEXT
       needlebench plan redo PLAN.json --run N [--reason TEXT]
       needlebench plan report SESSION_DIR [--by FACTOR,...] [--estimate-mass] [--json] [--out-dir DIR]
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+54"/>
        <location line="+152"/>
        <source>runs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-144"/>
        <source>the template (see &apos;plan templates&apos;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the plan file to write</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>listed | random | blocked (by site; default listed)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>seed of the random order and of the simulated runs (default 1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>change a default setting, e.g. cycles=3 (repeatable)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set a factor&apos;s levels, e.g. site=1,2,3 (repeatable; a new name adds a factor)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>replace an existing file (never a plan with recorded runs)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--template NAME is required (see &apos;needlebench plan templates&apos;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>unknown template &apos;%1&apos; (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>--out PLAN.json is required</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>--order must be listed, random or blocked (got &apos;%1&apos;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>--seed wants an integer from 0 to 4294967295 (got &apos;%1&apos;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>--set %1: expected KEY=VALUE with KEY one of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--set %1: %2 is a factor of this template; give its levels with --levels %2=...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--levels %1: expected FACTOR=L1,L2,...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>needlebench plan new: note: &apos;%1&apos; is neither a setting of the rig nor a factor of this template (%2); it is added as a new factor that the operator sets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 holds a plan with recorded runs; it is not overwritten</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: %2 runs of &apos;%3&apos;, order %4, seed %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+42"/>
        <source>the plan file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 min of motion left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+29"/>
        <source>the run&apos;s number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>why (required to skip)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the plan file (the session&apos;s plan.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--reason TEXT is required</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>--run: no run &apos;%1&apos; in %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+161"/>
        <source>run %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-150"/>
        <source>the session folder (created when missing; holds plan.json and the runs)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>sim | u6 | u6:SERIAL (default sim)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sim | zaber:PORT (default sim)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>on real devices, do not wait for Enter after an operator instruction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the plan (from &apos;plan new&apos;, or the session&apos;s plan.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--session DIR is required</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+27"/>
        <source>%1 holds a different plan; to resume it run &apos;needlebench plan run %1 --session %2&apos;, or use another session folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 is open in another NeedleBench (%2); close it there first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>recovered %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>run %1 had ended before the interruption: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>run %1 was interrupted; it runs again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+29"/>
        <source>the plan stops before run %1 (interrupted); run the same command again to resume</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>operator: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>press Enter when done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+25"/>
        <source>run %1 of %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>interrupted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the plan stops at run %1 (interrupted); run the same command again to resume</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>done (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the plan stops at run %1; fix the cause and run the same command again to resume</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+20"/>
        <location filename="../app/plan_runner.cpp" line="-27"/>
        <location filename="../app/simulated_run.cpp" line="+175"/>
        <source>cannot write %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Fitted quantities per run with their factor levels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+22"/>
        <source>factors to group by, comma separated (default: the plan&apos;s factors)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>fit friction with the mass estimated (eq. 19, as Table 5)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>also write the tables here as CSV and LaTeX (by_factor, friction_by_frequency, runs_by_factor)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>include runs the plan does not count (interrupted, discarded)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+27"/>
        <source>--by FACTOR,... is required when the folder has no plan.json</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+23"/>
        <source>%n run(s) the plan does not count (interrupted, failed or discarded) left out: %1; --all-runs includes them</source>
        <translation>
            <numerusform>%n run the plan does not count (interrupted, failed or discarded) left out: %1; --all-runs includes it</numerusform>
            <numerusform>%n runs the plan does not count (interrupted, failed or discarded) left out: %1; --all-runs includes them</numerusform>
        </translation>
    </message>
    <message>
        <location line="+9"/>
        <source>--by %1: no run in %2 records a level of it (factors recorded: %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>none; settings such as tissue or tip work too</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>cannot create %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+36"/>
        <source>no run in %1 could be fitted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+27"/>
        <source>needlebench plan: unknown subcommand &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cmd_sync.cpp" line="-1"/>
        <source>Find the video&apos;s offset to the force record (video time = recording time + offset).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the video of the run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>region of the picture that moves with the needle, in pixels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>largest offset to consider, seconds (default 20)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the needle&apos;s line in the picture, in pixels (default: found in the picture)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the video is as its camera or console coded it, never converted: its coder&apos;s lag is then known more closely</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>also write the needle&apos;s tracked displacement per frame (time_s,displacement_px) to FILE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>let --trace replace a file that is not a trace (an earlier trace is replaced without it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>needlebench sync: --roi wants x,y,w,h in whole pixels, w and h &gt; 0

</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>needlebench sync: --needle wants x1,y1,x2,y2 in pixels, two distinct points

</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>needlebench sync: --max-offset wants a positive number of seconds
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+35"/>
        <source>needlebench sync: %1: the picture is %2x%3 px, too small to show a needle (%4 px a side at least)
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>needlebench sync: --roi %1,%2,%3,%4 lies outside the %5x%6 picture
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>needlebench sync: --needle %1,%2,%3,%4 lies outside the %5x%6 picture
</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+14"/>
        <source>warning: %1: %n frame(s) in damaged stretches of the file, or after one up to the next keyframe, were left out</source>
        <translation>
            <numerusform>warning: %1: %n frame in a damaged stretch of the file, or after one up to the next keyframe, was left out</numerusform>
            <numerusform>warning: %1: %n frames in damaged stretches of the file, or after one up to the next keyframe, were left out</numerusform>
        </translation>
    </message>
    <message>
        <location line="+59"/>
        <source>offset:      %1 s (video time minus recording time)
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>offset:      none (nothing in the picture moved with the recording)
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>confidence:  %1
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>correlation: %1
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>reversed:    the needle in the picture moves against the recorded position (a mirrored picture, or the position&apos;s sign)
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>onsets say:  %1 s
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>drift:       %1 %
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>uncertainty: %1 frames
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>uncertainty: unknown (what moved in the picture does not time the offset)
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>uncertainty: unknown (nothing in the picture moved with the recording)
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>coded late:  %1 frames (taken off the offset), known to ±%2 frames
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>needle:      %1,%2 to %3,%4 (%5)
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>found in the picture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>given</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>method:      %1
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>tracked:     %1 to %2 s of %3 s (as far as the offsets tried reach)
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>LOW CONFIDENCE (below %1): check the offset by marking an event in both before using it
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the video&apos;s coder shows this slow needle late by an amount known only to ±%1 frames: a region or a needle line will not make it surer, an event marked in both will
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>if nobody converted this video (it is as its camera or console coded it), --coded-once narrows that
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>offsets were tried within ±%1 s (--max-offset): if the video started further from the recording than that, try a larger --max-offset
</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+12"/>
        <source>the video %1 has only %n frame(s)</source>
        <translation>
            <numerusform>the video %1 has only %n frame</numerusform>
            <numerusform>the video %1 has only %n frames</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>the run %1 has only %n sample(s)</source>
        <translation>
            <numerusform>the run %1 has only %n sample</numerusform>
            <numerusform>the run %1 has only %n samples</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>cannot synchronise %1 with %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cmd_video.cpp" line="-38"/>
        <source>Index a video file frame by frame and describe it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+34"/>
        <source>the video file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cmd_sync.cpp" line="-152"/>
        <location filename="../app/cmd_video.cpp" line="-24"/>
        <source>warning: %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cmd_video.cpp" line="+4"/>
        <source>file:        %1
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>codec:       %1
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>size:        %1x%2
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>frames:      %1
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rate:        %1 frames/s nominal%2
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>, variable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>duration:    %1 s
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>duplicates:  %1
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Write frame N (N-th in presentation order, from 0) of a video as an image.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>frame number, from 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>image to write (.png)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>needlebench frame: --index N (a whole number &gt;= 0) and --out IMAGE are required

</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>needlebench frame: --out %1: not an image type that can be written (use .png, .tif or .jpg)
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>needlebench frame: %1: frame %2 does not exist (the video has %3 frames)
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>needlebench frame: %1: %2
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>needlebench frame: %1: cannot write the image
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>frame %1 at %2 s written to %3
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli_support.cpp" line="+22"/>
        <source>show this help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>missing arguments</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>too many arguments</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+42"/>
        <source>%1 %2 is a file this command reads; writing it would destroy it. Name another file.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 %2 already exists; it is kept. Name another file, or add --overwrite to replace it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 %2 already exists and is not a trace this command wrote; it is kept. Name another file, or add --overwrite to replace it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 %2 is a folder; name a file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 %2: the folder %3 does not exist</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 %2: no file can be written in %3 (%4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>warning: %1 is a friction run (a sine on the platform, by its header); contact, punctures and stiffness are read for insertion runs and mean little here (&apos;needlebench fit friction&apos; fits it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands.cpp" line="+28"/>
        <source>print the version</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fit calibration, stiffness or friction models</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>find contact, punctures and relaxation in a run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>list connected DAQs and serial ports</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>record one run on real (or simulated) devices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>export a session as CSV, HDF5 or ELAN files</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>simulate, label, fit and export a short session</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>record one run on the simulated rig</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>index a video: frames, rate, duplicates</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>write one exact video frame as an image</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>find the video&apos;s offset to a run (motion vs needle speed)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>suggest phase and event labels for a run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>experiment plans: templates, new, run (resumes), report by factor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Usage: needlebench                 open the workbench (GUI, simulated rig)
       needlebench COMMAND [options]  run headless

Commands:
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>
&apos;needlebench COMMAND --help&apos; describes a command.
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>
Exit status: 0 done; 1 failed (the message says why, naming the file or device); 2 the command was given wrongly; 128+N ended by signal N (130 Ctrl+C, 143 SIGTERM), what was recorded closed.
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+22"/>
        <source>needlebench: unknown command &apos;%1&apos;

</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/plan_runner.cpp" line="-20"/>
        <source>cannot read %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: no column header</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+130"/>
        <source>the run did not start (exit code %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/guarded_main.cpp" line="+19"/>
        <source>out of memory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>unknown exception</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>internal error: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/simulated_run.cpp" line="-34"/>
        <source>interrupted while the video was rendered: %1 and the truth are not written; the run file %2 is whole</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: only %2 of %3 frames could be written (disk full?); removed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/main.cpp" line="+122"/>
        <source>needlebench %1: &apos;%2&apos; is not UTF-8, so it cannot be opened by name here: rename it (for example with convmv -f latin1 -t utf8 --notest)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>needlebench %1: the output could not be written (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>write error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Run a command without the window, such as &apos;needlebench demo&apos;; &apos;needlebench --help&apos; lists them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>needlebench: no display to open the workbench on (neither DISPLAY nor WAYLAND_DISPLAY is set). Log in to a desktop or use ssh -X.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>needlebench: the workbench cannot open on the display &apos;%1&apos; (see above): is the desktop still running, or the SSH session still forwarding X?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>needlebench: unknown option &apos;%1&apos;; &apos;needlebench --help&apos; lists the commands and their options</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>nb::TrCore</name>
    <message>
        <location filename="../core/export/dataset.cpp" line="+19"/>
        <source>time since the start of the recording</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>needle tip depth, grows as the needle goes deeper</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>needle velocity, recorded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>needle velocity, central differences of position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>needle acceleration, recorded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>needle acceleration, central differences of velocity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>axial force, positive when the tissue pushes back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the sensor&apos;s sample counter (a gap is a lost sample)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+21"/>
        <source>friction phase recorded with the run (the simulated rig&apos;s own)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>event recorded with the run at the sample</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>text recorded with the run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+151"/>
        <source>%1: frames numbered from the run&apos;s frame rate, the video could not be indexed (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/export/dataset_loader.cpp" line="+43"/>
        <source>%1: label &apos;%2&apos; (%3 s to %4 s) reaches beyond the run (%5 s to %6 s); its part from %7 s to %8 s is used</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+22"/>
        <source>not a folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>no such folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1: skipped, %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: left out, the run is still recording or was cut off before it was closed (export it after it ends; a cut-off run is recovered when its session is opened in the window)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+29"/>
        <source>%1: skipped, not a run file (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1: labels ignored (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1: its video %2 is missing; the export links none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-127"/>
        <source>%1: label &apos;%2&apos; (%3 s to %4 s) lies outside the run (%5 s to %6 s); ignored</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/export/run_csv_export.cpp" line="+78"/>
        <source>label of track &apos;%1&apos; active at the sample</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/export/csv_text.cpp" line="+37"/>
        <source>cannot write: no space left on the disk (%1 kB free)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../core/export/session_hdf5.cpp" line="+308"/>
        <location filename="../core/labels.cpp" line="+134"/>
        <location line="+11"/>
        <location filename="../core/plan.cpp" line="+983"/>
        <location filename="../core/run_file.cpp" line="+318"/>
        <location line="+40"/>
        <location line="+39"/>
        <location line="+14"/>
        <source>cannot write: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/export/session_analysis.cpp" line="+74"/>
        <source>%1: no stiffness fit (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1: no pooled stiffness fit (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+39"/>
        <location line="+19"/>
        <source>%1: no friction fit (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+64"/>
        <source>%1: no validation (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+51"/>
        <source>Pre-puncture stiffness fits per run, f = a1 x + a2 x^2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+50"/>
        <location line="+75"/>
        <source>run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/data_names.cpp" line="+53"/>
        <location filename="../core/export/session_analysis.cpp" line="-124"/>
        <location line="+26"/>
        <source>tissue</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/export/session_analysis.cpp" line="-23"/>
        <location line="+49"/>
        <source>rms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-47"/>
        <source>puncture depth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-168"/>
        <location line="+169"/>
        <source>puncture force</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-224"/>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+54"/>
        <source>model force at %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+26"/>
        <source>no tissue contact</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+145"/>
        <source>outlier</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/data_names.cpp" line="+47"/>
        <source>not fitted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>yes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/export/session_analysis.cpp" line="+17"/>
        <source>Pooled pre-puncture fits per tissue (Table 2 layout)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/data_names.cpp" line="-47"/>
        <location filename="../core/export/session_analysis.cpp" line="+3"/>
        <source>tip</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/export/session_analysis.cpp" line="+1"/>
        <source>fit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>mean puncture depth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mean puncture force</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+56"/>
        <source>runs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/data_names.cpp" line="+41"/>
        <source>pooled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>mean of runs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/export/session_analysis.cpp" line="-42"/>
        <source>Karnopp friction per unit length of needle in tissue, per run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+39"/>
        <source>f</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-35"/>
        <source>D from</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not determined</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Karnopp friction per unit length, mean and standard deviation per frequency and overall (Tables 4/5 layout)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/export/factor_analysis.cpp" line="+246"/>
        <location filename="../core/export/session_analysis.cpp" line="+2"/>
        <source>group</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <location filename="../core/export/session_analysis.cpp" line="+0"/>
        <source>statistic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/data_names.cpp" line="+8"/>
        <location filename="../core/export/factor_analysis.cpp" line="-29"/>
        <source>std</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/export/factor_analysis.cpp" line="-172"/>
        <source>%1: left out of the table: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+110"/>
        <source>%1: no friction fit with the mass estimated (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+55"/>
        <source>Fitted quantities by %1: mean, standard deviation and number of runs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>quantity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/data_names.cpp" line="-2"/>
        <location filename="../core/export/factor_analysis.cpp" line="+1"/>
        <source>mean</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/export/factor_analysis.cpp" line="+28"/>
        <source>Karnopp friction per unit length, mean and standard deviation per frequency and overall (Table 5 layout)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/data_names.cpp" line="+10"/>
        <source>unknown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-6"/>
        <source>overall</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>peak speeds</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-18"/>
        <source>peak speeds, %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/export/session_analysis.cpp" line="+34"/>
        <source>Summed model against the recorded insertions (Fig. 38)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>rms error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/export/session_hdf5.cpp" line="-255"/>
        <source>HDF5 could not %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+31"/>
        <location line="+14"/>
        <location line="+12"/>
        <source>create attribute &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-22"/>
        <location line="+12"/>
        <location line="+12"/>
        <source>write attribute &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+26"/>
        <source>set up compression for &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>create dataset &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+12"/>
        <location line="+21"/>
        <source>write dataset &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>create group &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+49"/>
        <source>one row per label; frames from the sync offset and frame rate of the run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>one row per label; no frames: the run has no video</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+22"/>
        <source>video frame index (0 = first frame); -1 outside the video</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>extreme force in the direction of motion; NaN when no sample lies in the interval</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NaN when no sample lies in the interval</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+29"/>
        <location line="+42"/>
        <source>another export is writing %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-41"/>
        <source>cannot create %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+43"/>
        <source>cannot create the file (is the folder writable?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>cannot create the file in memory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+25"/>
        <source>flush the file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-55"/>
        <source>cannot rename the finished file into place: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/calibration.cpp" line="+26"/>
        <source>calibration needs at least two points, got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>calibration point %1 is not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>calibration point %1 has a negative mass (%2 g)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>calibration needs at least two different masses</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>the voltage does not change with the mass (slope %1 V/g, standard error %2): is the sensor connected and its amplifier on?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <location filename="../core/labels.cpp" line="-80"/>
        <location filename="../core/run_file.cpp" line="-308"/>
        <source>cannot open: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+23"/>
        <source>header needs columns mass_g and voltage_V</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>expected %1 fields, got %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>mass_g and voltage_V must be numbers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>empty file (expected a header mass_g,voltage_V)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/labels.cpp" line="+24"/>
        <source>header has no &apos;%1&apos; column</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>start_s and end_s must be numbers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>end_s %1 is before start_s %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>empty label</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>no header row (expected track,label,start_s,end_s,comment)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1: row skipped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+50"/>
        <source>labels &apos;%1&apos; (%2 s to %3 s) and &apos;%4&apos; (%5 s to %6 s) overlap on track &apos;%7&apos;; &apos;%1&apos; is taken where they do</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/run_file.cpp" line="+6"/>
        <source>too large to read into memory (%1 MB)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <location filename="../core/session.cpp" line="+190"/>
        <source>binary data, not a text run file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/spreadsheet_separator.cpp" line="+18"/>
        <source>the columns are separated by &apos;%1&apos;, not by commas (a spreadsheet saving in a comma-decimal language?); save it as CSV with &apos;,&apos; between columns and &apos;.&apos; in numbers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>tab</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/run_file.cpp" line="+51"/>
        <source>header has no &apos;%1&apos; column (found: %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>column &apos;%1&apos; appears twice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1: ignored unknown columns: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>sample row after the closing metadata</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+26"/>
        <source>%1:%2: dropped a partial last row (recording was interrupted)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-20"/>
        <source>expected %1 fields, found %2%3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source> (file ends mid-row: interrupted recording?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+23"/>
        <source>column %1 (&apos;%2&apos;): &apos;%3&apos; is not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>time_s %1 does not increase (previous %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>file is empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <location filename="../core/session.cpp" line="+19"/>
        <source>no header row</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../core/run_plausibility.cpp" line="+21"/>
        <source>%1: force_N of %2 N at %3 s is beyond what any needle load cell reads (10 kN): a corrupt sample? (%n such sample(s))</source>
        <translation>
            <numerusform>%1: force_N of %2 N at %3 s is beyond what any needle load cell reads (10 kN): a corrupt sample? (%n such sample)</numerusform>
            <numerusform>%1: force_N of %2 N at %3 s is beyond what any needle load cell reads (10 kN): a corrupt sample? (%n such samples)</numerusform>
        </translation>
    </message>
    <message>
        <location line="+37"/>
        <source>%1: force_N stays at %2 N from %3 s to %4 s while the needle moves %5 mm: the sensor or its amplifier saturated there, and the force beyond it is not in the file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1: position_mm spans only %2 mm: if the positions were written in metres, they are 1000 times too small (position_mm is in millimetres)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/run_file.cpp" line="+94"/>
        <source>cannot write: no space left on the disk</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+34"/>
        <source>a run file is already open (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>another process is recording to this file; it was left untouched</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot lock: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+80"/>
        <location line="+16"/>
        <source>write failed after %1 rows: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/session.cpp" line="-163"/>
        <source>not valid JSON at byte %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>expected a JSON object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/end_reason.cpp" line="+45"/>
        <source>completed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ended by operator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>motion stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>emergency stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>force limit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stopped at puncture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>device fault</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>write error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>aborted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/session.cpp" line="+134"/>
        <source>its name is not UTF-8, so it cannot be opened by it; rename it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+66"/>
        <location line="+4"/>
        <source>cannot create the folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-2"/>
        <source>a session already exists here; open it instead</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>not a session folder (no %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+186"/>
        <source>process %1 on %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>its lock file %1 names no process; if no NeedleBench has it open, delete that file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/end_reason.cpp" line="+1"/>
        <source>recovered</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/session.cpp" line="-294"/>
        <source>unreadable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/events.cpp" line="+217"/>
        <source>too few samples before the puncture (%1) to fit the contact</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the needle does not move before the puncture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+44"/>
        <source>the contact fit failed (degenerate samples)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>too few samples (%1) for event detection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <location filename="../core/friction_fit.cpp" line="+616"/>
        <source>sample %1 is not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the needle does not move forward</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+53"/>
        <source>no puncture: the force never rises from contact and then drops sharply (by %1 N or %2 % of its peak)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+68"/>
        <source>the contact label at %1 s is outside the run (%2 to %3 s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+31"/>
        <source>the puncture label at %1 s is outside the run (%2 to %3 s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the puncture (%1 mm) is not past the contact (%2 mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/insertion_model.cpp" line="+16"/>
        <source>%1 time stamps for %2 positions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+36"/>
        <source>the runs to compare are empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>the simulated and recorded runs do not overlap in time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/stiffness_fit.cpp" line="+156"/>
        <source>too few samples (%1) between contact and puncture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>stiffness sample %1 is not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>stiffness sample %1 is %2 N: a corrupt sample</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>no depth past the contact point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>no runs to fit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/plan.cpp" line="-898"/>
        <source>neither motion nor protocol is set</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>motion &apos;%1&apos; does not go with protocol &apos;%2&apos; (sine motion is the friction protocol)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Move the slab to site %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Move the specimen to site %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Change to the %1 tip.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mount %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mount the %1 mm slab.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Set %1 to %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+108"/>
        <source>&apos;%1&apos; is not one of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>expected a tissue name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>expected a site number or name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+517"/>
        <source>expected true or false</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-513"/>
        <source>expected &quot;puncture&quot; or &quot;puncture:N&quot; (N &gt;= 1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+18"/>
        <source>%1 is outside %2 to %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-16"/>
        <source>expected a non-negative integer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+537"/>
        <source>expected a positive integer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-532"/>
        <source>expected a positive number, got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>expected a number or a text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+25"/>
        <source>21 insertions into whole liver 1, beveled tip, 4 mm/s (Table 2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>7 insertions into liver 7 with the capsule removed, blunt tip, 2.5 mm/s (Table 3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>liver 3 slab, sine 10 mm at 0.2/0.5/0.8 Hz at 7 locations, beveled tip (Table 4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>11 insertions into whole liver 5 with video, diamond tip, 4 mm/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>liver 7 slab with video, sine 10 mm at 0.2/0.5/0.8 Hz at 5 locations, diamond tip (Table 5)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>9 insertions into a canine prostate, diamond tip, 4 mm/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+32"/>
        <location line="+407"/>
        <source>a factor needs at least one level</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-383"/>
        <source>blocked order needs a factor named site</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+57"/>
        <source>Fit the %1 tip.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+29"/>
        <source>%1 Hz</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 mm/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>amplitude %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>depth %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>site %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>repeat %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 tip</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 cycles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 mm slab</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+66"/>
        <source>redone</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+137"/>
        <location line="+21"/>
        <source>missing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-17"/>
        <source>expected a text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+57"/>
        <location line="+41"/>
        <location line="+37"/>
        <source>expected an object {...}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-123"/>
        <source>expected a list [...]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&apos;%1&apos; is not an ISO 8601 date and time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&apos;%1&apos; is not a NeedleBench plan (expected %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>version %1 is not supported (this program reads version %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&apos;%1&apos; is not one of listed|random|blocked</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>&apos;%1&apos; is listed twice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+22"/>
        <source>unknown setting (known: %1; declare other factors under &quot;factors&quot;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+25"/>
        <source>run %1 is listed twice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&apos;%1&apos; is not one of pending|running|done|skipped|redone</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>(the reason was lost by an earlier version of NeedleBench)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>a run marked %1 needs the attempt that made it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+123"/>
        <source>cannot read: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>no such file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the file is empty; a plan is a JSON file (needlebench plan new writes one)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>line %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not JSON as a plan is written (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>expected a JSON object {...}</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../core/excerpt.cpp" line="+31"/>
        <source>… (%n more characters)</source>
        <translation>
            <numerusform>… (%n more character)</numerusform>
            <numerusform>… (%n more characters)</numerusform>
        </translation>
    </message>
    <message>
        <location line="+12"/>
        <source>… (%1 bytes in all)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/run_judgement.cpp" line="+47"/>
        <source>no end reason: the recording was cut off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>unknown end reason &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>ended early (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>no tissue contact (the force never rose above its noise)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1 %2 %3 is %4 %3 from the median %5 %3 (limit %6 %3: %7 MADs or %8 %)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/run_video_link.cpp" line="+30"/>
        <source>%1: cannot read (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: not a video link file (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+45"/>
        <source>set by hand</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>from marked events</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>automatic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>not synchronised</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+92"/>
        <location line="+3"/>
        <source>cannot write (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/friction_fit.cpp" line="-102"/>
        <source>too few samples (%1) to find the zero-velocity band</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>no motion: the zero-velocity band cannot be found</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+43"/>
        <source>too few sliding samples to find the zero-velocity band</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+39"/>
        <source>the tissue thickness must be positive, got %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the zero-velocity band must not be negative</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>too few samples (%1) for a friction fit (%2 are trimmed at each end)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 phase names for %2 samples</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 tissue velocities for %2 samples</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the tissue&apos;s velocity is measured at none of the run&apos;s samples (does the trace cover the run&apos;s time?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+61"/>
        <source>no phase c in the phases: the tissue never rested while the needle slid through it (a stroke longer than the slab&apos;s free travel gives phase c), so C and b cannot be measured</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>none of the %1 phase-c samples moves faster than the zero-velocity band (±%2 mm/s): in phase c as labelled the needle reaches only %3 mm/s of its %4 mm/s, so c lies only where it turns. The tissue may never have rested (a stroke within the slab&apos;s free travel carries it throughout): then C and b cannot be measured; else label c where the tissue rests while the needle is still fast</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>none of the %1 phase-c samples moves faster than the zero-velocity band (±%2 mm/s), the needle reaching %3 mm/s in phase c: check that c is labelled where the tissue rests, or give a narrower --band-m-s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>phase c in one direction only (%1 sliding samples moving in, %2 moving out, of %3 phase-c samples): the tissue hardly rested in the other</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>motion in one direction only (%1 samples moving in, %2 moving out)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+84"/>
        <source>the friction fit is singular (velocity does not vary within a direction)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+153"/>
        <source>Cp &lt; 0: dynamic friction cannot push the needle along</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cn &lt; 0: dynamic friction cannot push the needle along</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bp &lt; 0: damping cannot feed energy in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bn &lt; 0: damping cannot feed energy in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 = %2 ± %3 N·s/m is not determined by this run: it slides over too narrow a range of speeds</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 is not determined by this run: the tissue rests on the plate only while the needle slides between %2 and %3 mm/s, of a stroke reaching %4 mm/s, too narrow a range of speeds to carry its line down to zero speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+48"/>
        <source>%1 is not determined by the velocity band: in %2 of %3 stretches the force still rises where the band ends, the break-away not seen apart from the sliding (label phase a)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-65"/>
        <source>%1 rests on an undetermined %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1 and %2 are not determined by this run: its sliding force departs from the line by %3 times its noise (the tissue&apos;s give changes along the stroke)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 and %2 are not determined by this run: letting its sliding line bend moves %1 by %3 % (the tissue&apos;s give changes with speed; label phase c where the tissue rests)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-22"/>
        <source>%1 is not determined by this run: it slides only between %2 and %3 mm/s, too narrow a range of speeds to carry its line down to zero speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-270"/>
        <source>no sample moves faster than the zero-velocity band (±%1 mm/s), the needle&apos;s top speed being %2 mm/s: give a narrower --band-m-s, or label phase c</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+310"/>
        <source>Dp and Dn are not determined: the run has no stretch at rest (phase a) in both directions to read the static limits from</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Dp is not positive: the static limit in + motion has the wrong sign</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Dn is not negative: the static limit in - motion has the wrong sign</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>|Dp| &lt; |Cp|: static friction below dynamic friction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>|Dn| &lt; |Cn|: static friction below dynamic friction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/data_names.cpp" line="-98"/>
        <source>beveled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>diamond</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>blunt</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Liver %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Prostate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>linear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>sine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>insertion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>withdrawal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>events</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>motion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>site</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>repeat</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>cycles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>velocity [mm/s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>frequency [Hz]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>amplitude [mm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>depth [mm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>slab thickness [mm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>contact</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>puncture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>relaxation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>internal puncture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+30"/>
        <source>all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>stiffness</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+13"/>
        <source>internal stiffness</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-11"/>
        <location line="+13"/>
        <source>friction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-11"/>
        <location line="+17"/>
        <source>prostate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-10"/>
        <source>overall stiffness</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>stiffness under imaging</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>friction under imaging</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>phase a</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>velocity band</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>nominal (device)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/label_suggest.cpp" line="+238"/>
        <source>no puncture found in the force</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/surface_relaxation.cpp" line="+41"/>
        <source>too few frames to follow the surface</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the video does not show the puncture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+25"/>
        <source>no frames near the puncture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+54"/>
        <source>the surface&apos;s motion around the puncture could not be fitted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the surface&apos;s spring-back (%1 px) does not stand out of the picture&apos;s noise (%2 px)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>the video ends before the surface has come to rest</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the surface&apos;s motion after the puncture is not a spring-back that settles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the surface does not come to rest within %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-18"/>
        <source>nothing springs back after the puncture: the picture goes on moving the way the needle carried it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+27"/>
        <source>the surface springs back further (%1 px) than it was carried since the contact (%2 px): the picture lost the surface</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/export/kept_export.cpp" line="+33"/>
        <source>cannot keep the earlier export aside while the new one is written (cannot create %1): nothing was written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>cannot keep the earlier export aside while the new one is written (%1): nothing was written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/tissue_trace.cpp" line="+18"/>
        <source>cannot be read: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>is not a tissue trace: its first line must be &apos;%1&apos; (as labels suggest --tissue-trace writes it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <source>line %1 is not a time and a velocity: &apos;%2&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>line %1: the time %2 s does not follow %3 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>holds fewer than two measurements</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>nb::TrDevices</name>
    <message>
        <location filename="../devices/device_spec.cpp" line="+47"/>
        <source>unknown tissue &apos;%1&apos; (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>unknown tip &apos;%1&apos; (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>unknown setup &apos;%1&apos; (organ|platform)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&apos;%1&apos;: the U6 serial number must be digits (see &apos;needlebench devices&apos;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>unknown DAQ &apos;%1&apos; (sim | u6 | u6:SERIAL)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>unknown stage &apos;%1&apos; (sim | zaber:PORT)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+63"/>
        <source>simulated rig</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+24"/>
        <location filename="../devices/sim/simulated_rig.cpp" line="+52"/>
        <source>simulated load cell</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <location filename="../devices/sim/simulated_rig.cpp" line="-1"/>
        <source>simulated stage</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+52"/>
        <source>LabJack U6 (USB bus %1 device %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>USB</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../devices/labjack_u6/u6_force_sensor.cpp" line="+29"/>
        <source>cannot start libusb: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>sending a command failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>no reply for %1 ms (cable unplugged?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reading a reply failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>no permission to open it (install the udev rule for 0cd5:0006)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot open it: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>in use by another program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>cannot claim it: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+69"/>
        <source>bus %1 device %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <source>not found on USB (is it plugged in?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>reading calibration block %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>calibration memory looks corrupt (gain %1 slope %2 V/count)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+41"/>
        <source>unplugged (the USB device is gone)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <location filename="../devices/labjack_u6/u6_protocol.cpp" line="+177"/>
        <source>short reply (%1 of %2 bytes)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>StreamStop failed with device error %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>StreamConfig rejected with device error %1 (rate %2 Hz too high for this resolution?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>StreamStart failed with device error %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+24"/>
        <source>StreamStop answered device error %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <location filename="../devices/sim/simulated_rig.cpp" line="+145"/>
        <source>read while not streaming</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>unplugged during the stream (USB device gone); samples up to %1 s were received</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>stream read failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>USB transfer overflow</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>no stream data for %1 ms (cable unplugged or device stalled?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>stream transfer of %1 bytes is not whole packets; the rest is dropped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>dropped a stream packet: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 corrupt stream packets in a row (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 stream packet(s) lost before packet %2 (%3 samples)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>device stream buffer overflowed (backlog %1); the device is recovering</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>device recovered from an overflow; %1 samples were lost</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>stream error %1 reported by the device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../devices/labjack_u6/u6_protocol.cpp" line="+5"/>
        <source>the device reported a checksum error in our command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>unexpected reply header %1 %2 %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+23"/>
        <source>reply checksum mismatch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-11"/>
        <source>short reply (%1 of 4 bytes)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>unexpected reply %1 to command %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>ConfigU6 failed with device error %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>reading calibration failed with device error %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+61"/>
        <source>short stream packet (%1 bytes)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>not a stream data packet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>stream packet checksum mismatch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../devices/realtime.cpp" line="+38"/>
        <source>real-time scheduling (SCHED_FIFO) not permitted: %1; sample timing may jitter (grant rtprio in /etc/security/limits.conf or CAP_SYS_NICE)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>memory not locked (sanitizer build)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>memory could not be locked (mlockall: %1); page faults may delay samples</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../devices/sim/imaging_render.cpp" line="+145"/>
        <source>the run has too few samples to render</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-6"/>
        <source>unknown video type &apos;.%1&apos; (use .avi, .mkv or .mp4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+26"/>
        <source>cannot write a video here (folder missing or not writable, or no encoder)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the video would start %1 s after the recording began, after its end (%2 s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>the video could not be written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../devices/sim/simulated_rig.cpp" line="-65"/>
        <source>no reply for 100 ms to &apos;%1&apos; (cable unplugged?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>rejected &apos;%1&apos;: controller reports a fault (RJ)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>rejected &apos;%1&apos;: driver disabled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+15"/>
        <source>no reply for 100 ms (cable unplugged?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-13"/>
        <source>rejected &apos;driver enable&apos;: controller reports a fault (RJ)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+21"/>
        <source>stream start failed: LIBUSB_ERROR_IO</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+29"/>
        <source>stream error: USB transfer failed (LIBUSB_ERROR_IO)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>no samples for %1 ms (cable unplugged?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+111"/>
        <source>target %1 mm is outside the travel (%2 to %3 mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+32"/>
        <source>unknown tissue &apos;%1&apos; (known: %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../video/frame_index.cpp" line="+283"/>
        <location filename="../video/packet_index.cpp" line="+21"/>
        <source>no such file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not a readable file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the file is empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>cannot open as video: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>an MP4/MOV file without its index (the &apos;moov&apos; box written when a recording is closed): the recording was cut off before it was finished, and its frames cannot be found without that index</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>an MP4/MOV file with no video FFmpeg can read (sound only, or a video codec this system lacks)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>cannot open as video (not a video file, or a format FFmpeg does not read)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-213"/>
        <source>the file says its picture is turned by %1°: shown turned, as players show it</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="-14"/>
        <source>the file&apos;s first %1 s are damaged: %n packet(s) there could not be decoded; its frames start at %1 s</source>
        <translation>
            <numerusform>the file&apos;s first %1 s are damaged: %n packet there could not be decoded; its frames start at %1 s</numerusform>
            <numerusform>the file&apos;s first %1 s are damaged: %n packets there could not be decoded; its frames start at %1 s</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>the file is damaged between %1 s and %2 s: %n packet(s) there could not be decoded and are left out; the frames on either side are read</source>
        <translation>
            <numerusform>the file is damaged between %1 s and %2 s: %n packet there could not be decoded and is left out; the frames on either side are read</numerusform>
            <numerusform>the file is damaged between %1 s and %2 s: %n packets there could not be decoded and are left out; the frames on either side are read</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>and %n more damaged stretch(es)</source>
        <translation>
            <numerusform>and %n more damaged stretch</numerusform>
            <numerusform>and %n more damaged stretches</numerusform>
        </translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the file holds %1 video streams: only the first (%2x%3) is shown and measured</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+277"/>
        <location filename="../video/packet_index.cpp" line="+45"/>
        <location line="+8"/>
        <source>no frame could be decoded (truncated or corrupt file?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-299"/>
        <source>only %1 of %2 frames are readable: the file is cut off, or damaged after that frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>frame timestamps are not increasing: frames are reached by decoding from the start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../video/frame_reader.cpp" line="+18"/>
        <source>the video has no indexed frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+22"/>
        <source>cannot reopen the video (moved or deleted?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+90"/>
        <source>frame %1 does not exist (the video has %2 frames)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>frame %1 lies in a damaged stretch of the file and cannot be decoded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+28"/>
        <source>frame %1 could not be decoded (truncated or changed file?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>frame %1 could not be decoded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../devices/zaber/zaber_stage.cpp" line="+54"/>
        <source>cannot open the serial port: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Zaber stage on %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+24"/>
        <source>ignored a garbled line: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>serial port failed: %1 (cable unplugged?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>controller fault %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>writing to the serial port failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>no reply to &apos;%1&apos; within %2 ms (cable unplugged or controller off?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>&apos;%1&apos; rejected: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+28"/>
        <source>target %1 mm is outside the travel %2..%3 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>speed must be positive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>sine %1 mm at %2 Hz needs %3 mm/s, above the %4 mm/s limit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>sine of %1 mm around %2 mm leaves the travel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+46"/>
        <source>position reply is not a number: &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../devices/interlocks.cpp" line="+22"/>
        <source>A run is recording: end it before %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The stage is moving: stop it before %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>The stage is not moving.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>changing the session, devices or language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>quitting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Device fault: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The devices are not running.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+73"/>
        <location line="+10"/>
        <source>Stop the motion first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-81"/>
        <source>End the run first: disabling the drive would end the experiment unrecorded.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Bias needs the stage at rest.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Biasing during a run would shift its forces; end the run first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The force is above the noise band: bias with the needle free of tissue.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The needle is past the depth where it met tissue: withdraw it before biasing.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+20"/>
        <location line="+31"/>
        <location line="+12"/>
        <source>Enable the stage first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-61"/>
        <source>Zeroing needs the stage at rest.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Zeroing during a run would shift its positions; end the run first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The needle is past the depth where it met tissue: zero with the tip at the start position.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The force is above the noise band: zero with the needle free of tissue.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The motion of a run is fixed while it records or moves.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+33"/>
        <location line="+12"/>
        <source>Emergency stop: enable the stage again to reset it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-43"/>
        <source>Open or create a session first: the run needs a folder.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Bias the force sensor first (needle free of tissue).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+31"/>
        <source>Zero the stage position first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-29"/>
        <source>No active calibration: calibrate the sensor or choose a calibration.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The calibration wizard is open: finish or close it before a run.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Set a maximum-force limit first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A run is already recording: end it first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The force is %1 N, near the %2 N limit: withdraw the needle first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+40"/>
        <source>The stage is moving.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-16"/>
        <source>Jogging is never recorded: end the run first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>No run is recording.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stop the motion first: End run closes the file, it does not stop the stage.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Calibration changes the forces of a run; end the run first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../devices/run_once.cpp" line="+58"/>
        <source>the devices did not get ready within %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>interrupted before the run ended</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the run did not finish within %1 minutes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../devices/sim/simulated_devices.cpp" line="+19"/>
        <source>simulated rig (%1, %2 tip, seed %3%4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>, simulated clock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../devices/zaber/zaber_protocol.cpp" line="+96"/>
        <source>the controller is busy; try again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no such axis on this controller</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the controller does not know this command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a value is out of range for this stage</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bad message id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the command must be sent to the whole device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the motor driver is disabled (enable it; check motor power)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the controller&apos;s buffer is full</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the axis is in lockstep</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>access level too low for this setting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the axis is parked (unpark it first)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the controller is under remote control</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the axis is moving</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the axis has not been homed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the controller reports a system error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>rejected: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>stalled and stopped (obstruction or overload?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>limit error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>encoder error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>driver disabled by a fault (over-temperature or power)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../video/needle_tracker.cpp" line="+778"/>
        <source>the needle line lies outside the picture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the needle line does not cross the region %1,%2 %3x%4 (at least 20 pixels of it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../video/frame_index.cpp" line="+9"/>
        <source>indexed from the file&apos;s packets: repeated pictures are not flagged as duplicates</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../devices/recorder.cpp" line="+63"/>
        <source>a run is already being recorded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>only %1 kB free on the disk; a recording needs at least %2 kB</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+94"/>
        <source>the disk holding %1 will be full in about %2 s (%3 kB free)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../video/tissue_tracker.cpp" line="+96"/>
        <source>the region for the tissue&apos;s motion is too small or outside the picture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+21"/>
        <source>no frame of the video could be decoded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+158"/>
        <source>too few frames or samples to follow the tissue</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+41"/>
        <source>the needle does not move while the video runs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>nothing in the picture moves with the needle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+25"/>
        <source>the tissue&apos;s motion does not stand out of the picture&apos;s noise</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../video/labels_from_video.cpp" line="+35"/>
        <source>stopped before the video was read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>too few distinct frames to follow the surface</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+20"/>
        <source>the video gave no motion to read</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>nb::TrViews</name>
    <message>
        <location filename="../widgets/analysis/analysis_plots.cpp" line="+112"/>
        <source>Stiffness before puncture: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>depth past contact [mm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+117"/>
        <location line="+58"/>
        <source>force [N]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-149"/>
        <source>%1 (outlier)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Friction against velocity: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>friction force [N]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+125"/>
        <source>recorded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-74"/>
        <source>Karnopp fit (%1 Hz)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-109"/>
        <location filename="../widgets/analysis/analysis_workspace.cpp" line="-705"/>
        <location line="+491"/>
        <source>no tissue given</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+50"/>
        <source>pooled fit:
F = %1 x + %2 x²
(F in N, x in mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>velocity [mm/s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+28"/>
        <source>recorded, not fitted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>recorded, fitted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Labelled phases: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>time [s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>force</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>force, insertion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>force, withdrawal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+27"/>
        <source>phase %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Model against recording: %1 (rms %2 N)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Model against recording: %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>needle position [mm]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>summed model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 by %2: mean ± std, n per level</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>(none)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+22"/>
        <source>runs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mean ± std</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/analysis/figure_export.cpp" line="+44"/>
        <source>unknown figure format &apos;%1&apos; (png, svg or pdf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>could not render the figure</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>cannot write the figure</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/label_commands.cpp" line="+12"/>
        <source>add %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>delete %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>edit %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>split %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>nb::VideoView</name>
    <message>
        <location filename="../widgets/video_view.cpp" line="+22"/>
        <source>Open video…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>attach the video filmed during this run (or drop the file here)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>No video. Open one, or drop the file here, to review it with the force record.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+110"/>
        <source>frame %1   %2 s</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>nb::WelcomeDialog</name>
    <message>
        <location filename="../widgets/welcome_dialog.cpp" line="+17"/>
        <location line="+31"/>
        <source>Welcome to NeedleBench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-30"/>
        <source>A session is a folder for one specimen: its calibration, its runs, their videos and labels. Start a new one or continue one.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;New session…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Open session folder…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 (not found)
%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No session is in this folder any more: moved, renamed, or on a drive not connected. Open it where it is now with Open session folder…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Recent sessions (double-click to open):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>No recent sessions.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Not now</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>look around without a session; runs need one</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>nb::devices::AcquisitionEngine</name>
    <message>
        <location filename="../devices/acquisition_engine.cpp" line="+200"/>
        <source>stage enabled; fault cleared</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>stage enabled; emergency stop reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>stage enabled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>stage disabled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>biasing the force sensor: averaging %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>stage position zeroed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>force limit must be positive (got %1 N)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>force limit %1 N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+25"/>
        <source>withdrawal force limit must be positive (got %1 N)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>withdrawal force limit %1 N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>calibration refused: slope must be positive (got %1 V/g)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+13"/>
        <source>calibration refused: a run is recording; end the run first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-8"/>
        <source>calibration &apos;%1&apos;: %2 V/g</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+26"/>
        <location line="+49"/>
        <source>run not started: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+25"/>
        <source>recording to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+82"/>
        <source>motion stopped; still recording</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>motion stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+148"/>
        <source>run ended (%1): %2 samples, %3 dropped, %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+29"/>
        <source>could not stop the stage: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>fault: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+28"/>
        <source>force limit: the load cell&apos;s reading reached the end of its input range at %1 N (%2 mm): the force may be higher; stage stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+29"/>
        <source>puncture %1 at %2 mm: stage stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>puncture at %1 mm: slowing to %2 mm/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+69"/>
        <location line="+105"/>
        <source>warning: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-103"/>
        <source>real-time scheduling not requested</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+99"/>
        <source>recording failed, stage stopped: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-219"/>
        <source>force sensor biased: V0 = %1 V (%2 samples)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-465"/>
        <source>bias refused: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>zero refused: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+36"/>
        <source>warning: the load cell reads up to %1 N (its ±%2 V input), less than the force limit of %3 N: the stage stops there</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+60"/>
        <source>a run is already on its way to its start position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>run not started: the start position %1 mm is outside the travel (%2 to %3 mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>moving to the start position %1 mm (not recorded)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+91"/>
        <source>withdraw refused: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>withdrawing to %1 mm; this is recorded in the open run %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>withdrawing to %1 mm (not recorded: no run open)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>move refused: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>move refused: %1 mm is outside the travel (%2 to %3 mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>moving to %1 mm (not recorded)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+54"/>
        <source>could not disable the stage after the emergency stop: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>emergency stop: the stage is disabled until you enable it again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+171"/>
        <source>force limit: %1 N &gt; %2 N at %3 mm; stage stopped</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>

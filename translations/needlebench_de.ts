<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>QObject</name>
    <message>
        <location filename="../widgets/control_panel.cpp" line="+46"/>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>no</source>
        <translation>nein</translation>
    </message>
</context>
<context>
    <name>nb::AnalysisWorkspace</name>
    <message>
        <location filename="../widgets/analysis/analysis_workspace.cpp" line="+137"/>
        <source>Runs in the analysis:</source>
        <translation>Läufe in der Auswertung:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Include runs cut short
or without contact</source>
        <translation>Auch abgebrochene Läufe
oder ohne Kontakt einbeziehen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Runs ended by the force limit, an emergency stop or a fault end where the protection acted, not where the tissue gave way; runs that never touched tissue have nothing to fit. They are left out unless this is on.</source>
        <translation>Läufe, die die Kraftgrenze, ein Not-Halt oder ein Fehler beendete, enden dort, wo der Schutz eingriff, nicht wo das Gewebe nachgab; Läufe ohne Gewebekontakt haben nichts anzupassen. Sie bleiben draußen, solange dies aus ist.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Reload labels</source>
        <translation>Labels neu laden</translation>
    </message>
    <message>
        <location line="+38"/>
        <location line="+490"/>
        <source>Save figure…</source>
        <translation>Abbildung speichern…</translation>
    </message>
    <message>
        <location line="-489"/>
        <location line="+490"/>
        <source>Save tables…</source>
        <translation>Tabellen speichern…</translation>
    </message>
    <message>
        <location line="-454"/>
        <source>Stiffness</source>
        <translation>Steifigkeit</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Tissue:</source>
        <translation>Gewebe:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Friction</source>
        <translation>Reibung</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+1"/>
        <source>Run:</source>
        <translation>Lauf:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Validation</source>
        <translation>Validierung</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+2"/>
        <source>Per run</source>
        <translation>Je Lauf</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Pooled per tissue</source>
        <translation>Gepoolt je Gewebe</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Summary</source>
        <translation>Zusammenfassung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>By factor</source>
        <translation>Nach Faktor</translation>
    </message>
    <message numerus="yes">
        <location line="+227"/>
        <source>%n run(s) analysed</source>
        <translation>
            <numerusform>%n Lauf ausgewertet</numerusform>
            <numerusform>%n Läufe ausgewertet</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Left out (switch above to include them):</source>
        <translation>Ausgelassen (oben einschaltbar):</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+14"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="-12"/>
        <source>Outliers:</source>
        <translation>Ausreißer:</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: C departs from the peak-speed line (Cp %2 %, Cn %3 %); see Friction ▸ Summary</source>
        <translation>%1: C weicht von der Geraden durch die Spitzengeschwindigkeiten ab (Cp %2 %, Cn %3 %); siehe Reibung ▸ Zusammenfassung</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Fitted, with doubts:</source>
        <translation>Gefittet, mit Zweifeln:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Not fitted:</source>
        <translation>Nicht gefittet:</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>made again in the plan: %1</source>
        <translation>im Plan wiederholt: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>left out by default: %1</source>
        <translation>standardmäßig ausgelassen: %1</translation>
    </message>
    <message>
        <location line="+52"/>
        <location line="+15"/>
        <source>cannot create the folder</source>
        <translation>der Ordner kann nicht angelegt werden</translation>
    </message>
    <message>
        <location line="+83"/>
        <source>The factors of a plan&apos;s runs (their factor_… metadata)</source>
        <translation>Die Faktoren der Planläufe (ihre factor_…-Metadaten)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Quantity:</source>
        <translation>Größe:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>against factor:</source>
        <translation>gegen Faktor:</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>no factor</source>
        <translation>kein Faktor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no fitted quantity</source>
        <translation>keine angepasste Größe</translation>
    </message>
    <message>
        <location line="+33"/>
        <location line="+23"/>
        <source>no run</source>
        <translation>kein Lauf</translation>
    </message>
    <message>
        <location line="+16"/>
        <location line="+10"/>
        <source>Save figure</source>
        <translation>Abbildung speichern</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)</source>
        <translation>PNG-Bild (*.png);;SVG-Zeichnung (*.svg);;PDF-Dokument (*.pdf)</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Save tables (CSV and LaTeX) into</source>
        <translation>Tabellen (CSV und LaTeX) speichern in</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Save tables</source>
        <translation>Tabellen speichern</translation>
    </message>
</context>
<context>
    <name>nb::CalibrationWizard</name>
    <message>
        <location filename="../widgets/calibration_wizard.cpp" line="+30"/>
        <source>Calibrate force sensor – %1</source>
        <translation>Kraftsensor kalibrieren – %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source> g</source>
        <translation> g</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Set masses</source>
        <translation>Massen setzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Replaces the table with these masses (individual masses can be edited in the table)</source>
        <translation>Ersetzt die Tabelle durch diese Massen (einzelne Massen lassen sich in der Tabelle ändern)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Masses from</source>
        <translation>Massen von</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>to</source>
        <translation>bis</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Mass [g]</source>
        <translation>Masse [g]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Voltage [V]</source>
        <translation>Spannung [V]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Residual [mV]</source>
        <translation>Residuum [mV]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Use</source>
        <translation>Verwenden</translation>
    </message>
    <message>
        <location line="+25"/>
        <location line="+5"/>
        <source>mass [g]</source>
        <translation>Masse [g]</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>voltage [V]</source>
        <translation>Spannung [V]</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>residual [mV]</source>
        <translation>Residuum [mV]</translation>
    </message>
    <message>
        <location line="+17"/>
        <location line="+373"/>
        <source>No fit yet: measure at least two masses.</source>
        <translation>Noch kein Fit: mindestens zwei Massen messen.</translation>
    </message>
    <message>
        <location line="-360"/>
        <source>Measure</source>
        <translation>Messen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Waits until the reading settles, then averages the sensor voltage over the dwell time for the selected mass</source>
        <translation>Wartet, bis sich der Messwert beruhigt, und mittelt dann die Sensorspannung über die Verweilzeit für die gewählte Masse</translation>
    </message>
    <message>
        <location line="+73"/>
        <source>Step %1 of %2: the rig hangs %3 g; press Measure.</source>
        <translation>Schritt %1 von %2: der Versuchsstand hängt %3 g an; Messen drücken.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Step %1 of %2: hang %3 g on the sensor, then press Measure.</source>
        <translation>Schritt %1 von %2: %3 g an den Sensor hängen, dann Messen drücken.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>saturated</source>
        <translation>übersteuert</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 g saturates the input (%2 V, the range ends at ±%3 V): the point is refused. Calibrate only up to the masses the sensor can read.</source>
        <translation>%1 g übersteuert den Eingang (%2 V, der Bereich endet bei ±%3 V): der Punkt wird abgelehnt. Nur bis zu Massen kalibrieren, die der Sensor lesen kann.</translation>
    </message>
    <message numerus="yes">
        <location line="+66"/>
        <source>Discard the %n point(s) measured? They are not saved.</source>
        <translation>
            <numerusform>Den %n gemessenen Punkt verwerfen? Er ist nicht gespeichert.</numerusform>
            <numerusform>Die %n gemessenen Punkte verwerfen? Sie sind nicht gespeichert.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+68"/>
        <source>Step %1 of %2: %3 g – waiting for the reading to settle, then averaging %4 s; keep the mass still…</source>
        <translation>Schritt %1 von %2: %3 g – warte, bis sich der Messwert beruhigt, dann %4 s mitteln; die Masse ruhig halten…</translation>
    </message>
    <message>
        <location line="+83"/>
        <source>All masses measured: check the fit and its residuals, then Save and use.</source>
        <translation>Alle Massen gemessen: Anpassung und Residuen prüfen, dann Speichern und verwenden.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>All masses measured, but there is no fit yet.</source>
        <translation>Alle Massen gemessen, aber noch keine Anpassung.</translation>
    </message>
    <message>
        <location line="-305"/>
        <source>Measure all</source>
        <translation>Alle messen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Measures every row in turn</source>
        <translation>Misst jede Zeile der Reihe nach</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save and use</source>
        <translation>Speichern und verwenden</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Saves this calibration in the session and uses it for every following run</source>
        <translation>Speichert diese Kalibrierung in der Sitzung und verwendet sie für alle folgenden Läufe</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location line="+334"/>
        <source>d = %1 mV/g,  c = %2 V,  r² = %3,  rms residual = %4 mV,  %5 points</source>
        <translation>d = %1 mV/g,  c = %2 V,  r² = %3,  RMS-Residuum = %4 mV,  %5 Punkte</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Suspect point: %1 g lies %2× the scatter of the other points off their line. Untick it to leave it out.</source>
        <translation>Verdächtiger Punkt: %1 g liegt %2-mal so weit neben der Geraden der übrigen Punkte wie deren Streuung. Haken entfernen, um ihn auszulassen.</translation>
    </message>
</context>
<context>
    <name>nb::ControlPanel</name>
    <message>
        <location filename="../widgets/control_panel.cpp" line="+23"/>
        <source>EMERGENCY STOP (Esc)</source>
        <translation>NOT-HALT (Esc)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stops the stage at once and ends the run (always available; key: Esc)</source>
        <translation>Hält die Achse sofort an und beendet den Lauf (immer verfügbar; Taste: Esc)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>1. Prepare</source>
        <translation>1. Vorbereiten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Powers the stage drive</source>
        <translation>Schaltet den Antrieb der Achse ein</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Takes the present force as zero (needle free of tissue)</source>
        <translation>Nimmt die aktuelle Kraft als Null (Nadel frei vom Gewebe)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Makes the present stage position 0 mm</source>
        <translation>Setzt die aktuelle Achsposition auf 0 mm</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Calibrate sensor…</source>
        <translation>Sensor kalibrieren…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Known masses on the load cell, fit V = d·m + c</source>
        <translation>Bekannte Massen an der Kraftmessdose, Fit V = d·m + c</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+290"/>
        <source>2. Motion</source>
        <translation>2. Bewegung</translation>
    </message>
    <message>
        <location line="-287"/>
        <source>Linear</source>
        <translation>Linear</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sinusoidal</source>
        <translation>Sinusförmig</translation>
    </message>
    <message>
        <location line="+11"/>
        <source> mm/s</source>
        <translation> mm/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+14"/>
        <location line="+12"/>
        <location line="+469"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location line="-487"/>
        <source>Velocity</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Depth</source>
        <translation>Tiefe</translation>
    </message>
    <message>
        <location line="+6"/>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Amplitude</source>
        <translation>Amplitude</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frequency</source>
        <translation>Frequenz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cycles</source>
        <translation>Zyklen</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>3. Run</source>
        <translation>3. Lauf</translation>
    </message>
    <message>
        <location line="+467"/>
        <source>To start (%1 mm)</source>
        <translation>Zum Start (%1 mm)</translation>
    </message>
    <message>
        <location line="-555"/>
        <location line="+445"/>
        <source>&amp;Enable stage</source>
        <translation>Achse &amp;einschalten</translation>
    </message>
    <message>
        <location line="-442"/>
        <source>&amp;Bias force sensor</source>
        <translation>Kraftsensor &amp;tarieren</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Zero position</source>
        <translation>Position &amp;nullen</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>The sine oscillates about this depth; the needle moves there first (not recorded)</source>
        <translation>Der Sinus schwingt um diese Tiefe; die Nadel fährt zuerst dorthin (nicht aufgezeichnet)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Centre depth</source>
        <translation>Mittentiefe</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Start &amp;insertion (moves + records)</source>
        <translation>E&amp;instich starten (bewegt + zeichnet auf)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Starts recording a new run file, then moves the needle in</source>
        <translation>Beginnt die Aufzeichnung einer neuen Laufdatei und fährt dann die Nadel ein</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Withdraw</source>
        <translation>Zurückziehen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Moves the needle back to 0 mm</source>
        <translation>Fährt die Nadel zurück auf 0 mm</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Decelerates the stage; the run keeps recording until End run</source>
        <translation>Bremst die Achse ab; der Lauf zeichnet weiter auf bis „Lauf beenden“</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Stops recording and closes the run file</source>
        <translation>Beendet die Aufzeichnung und schließt die Laufdatei</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Maximum force</source>
        <translation>Maximale Kraft</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+11"/>
        <source> N</source>
        <translation> N</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>The stage stops at once when the force reaches this (0 = no limit: runs refused)</source>
        <translation>Die Achse hält sofort an, wenn die Kraft diesen Wert erreicht (0 = keine Grenze: Läufe werden verweigert)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Withdrawal</source>
        <translation>Rückzug</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>|F| that stops the needle coming out (never below the maximum force, so a limit stop never traps the needle)</source>
        <translation>|F|, bei dem das Zurückziehen stoppt (nie unter der maximalen Kraft, damit ein Grenzstopp die Nadel nie festhält)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Stage</source>
        <translation>Achse</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Bias done</source>
        <translation>Tariert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zero done</source>
        <translation>Genullt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Moving</source>
        <translation>Bewegung</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Force</source>
        <translation>Kraft</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Position</source>
        <translation>Position</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Dropped</source>
        <translation>Verloren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Recording</source>
        <translation>Aufzeichnung</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Calibration</source>
        <translation>Kalibrierung</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Fault</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <location line="+236"/>
        <source>The sine would reach %1 mm, past the stage&apos;s travel.</source>
        <translation>Der Sinus würde %1 mm erreichen, jenseits des Verfahrwegs der Achse.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The sine would go above 0 mm: make the centre at least the amplitude.</source>
        <translation>Der Sinus würde über 0 mm hinausfahren: Die Mitte muss mindestens so groß wie die Amplitude sein.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The depth (%1 mm) is not deeper than the needle is now (%2 mm).</source>
        <translation>Die Tiefe (%1 mm) liegt nicht tiefer als die Nadel jetzt (%2 mm).</translation>
    </message>
    <message>
        <location line="+40"/>
        <location line="+110"/>
        <location line="+9"/>
        <source>Not now: %1</source>
        <translation>Jetzt nicht: %1</translation>
    </message>
    <message>
        <location line="-112"/>
        <source>Disable stage</source>
        <translation>Achse ausschalten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Withdraw (not recorded)</source>
        <translation>Rückzug (ohne Aufnahme)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>stopped</source>
        <translation>angehalten</translation>
    </message>
    <message>
        <location line="-272"/>
        <location line="+273"/>
        <source>enabled</source>
        <translation>eingeschaltet</translation>
    </message>
    <message>
        <location line="-273"/>
        <location line="+273"/>
        <source>disabled</source>
        <translation>ausgeschaltet</translation>
    </message>
    <message>
        <location line="-275"/>
        <location line="+276"/>
        <source>yes (%1 V)</source>
        <translation>ja (%1 V)</translation>
    </message>
    <message>
        <location line="-274"/>
        <location line="+276"/>
        <source>at rest</source>
        <translation>in Ruhe</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not recording</source>
        <translation>keine Aufzeichnung</translation>
    </message>
    <message>
        <location line="-280"/>
        <location line="+274"/>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 (overruns %2)</source>
        <translation>%1 (Überläufe %2)</translation>
    </message>
    <message>
        <location line="-281"/>
        <location line="+282"/>
        <source>%1 N</source>
        <translation>%1 N</translation>
    </message>
    <message>
        <location line="-281"/>
        <location line="+282"/>
        <location line="+45"/>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <location line="-326"/>
        <location line="+286"/>
        <source>%1 N (%2 %)</source>
        <translation>%1 N (%2 %)</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+3"/>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>force limit tripped</source>
        <translation>Kraftgrenze ausgelöst</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&lt;b&gt;EMERGENCY STOP — latched.&lt;/b&gt;&lt;br&gt;The stage is disabled. Check the rig, then reset: this enables the stage again.</source>
        <translation>&lt;b&gt;NOT-HALT — verriegelt.&lt;/b&gt;&lt;br&gt;Die Achse ist ausgeschaltet. Versuchsstand prüfen, dann zurücksetzen: Das schaltet die Achse wieder ein.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Reset emergency stop (enable stage)</source>
        <translation>Not-Halt zurücksetzen (Achse einschalten)</translation>
    </message>
    <message>
        <location line="-293"/>
        <source>Jog (never recorded)</source>
        <translation>Tippbetrieb (nie aufgezeichnet)</translation>
    </message>
    <message>
        <location line="-109"/>
        <location line="+351"/>
        <source>Stop (keeps recording)</source>
        <translation>Stopp (zeichnet weiter)</translation>
    </message>
    <message>
        <location line="-347"/>
        <source>End run (closes file)</source>
        <translation>Lauf beenden (Datei zu)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Max. force</source>
        <translation>Max. Kraft</translation>
    </message>
    <message>
        <location line="+20"/>
        <location line="+425"/>
        <source>To start</source>
        <translation>Zum Start</translation>
    </message>
    <message>
        <location line="-403"/>
        <source>Sampling</source>
        <translation>Abtastung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Margin</source>
        <translation>Reserve</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Force left before the maximum force stops the stage</source>
        <translation>Kraft, die bis zum Stopp durch die maximale Kraft noch bleibt</translation>
    </message>
    <message>
        <location line="+26"/>
        <location line="+277"/>
        <source>%1 mm/s</source>
        <translation>%1 mm/s</translation>
    </message>
    <message>
        <location line="-257"/>
        <source>Unrecorded moves of the needle: steps in and out, or to a position</source>
        <translation>Bewegungen der Nadel ohne Aufzeichnung: Schritte hinein und heraus oder zu einer Position</translation>
    </message>
    <message>
        <location line="+68"/>
        <source>%1 %2 cannot be set here (%3 to %4 in steps of %5)</source>
        <translation>%1 %2 lässt sich hier nicht einstellen (%3 bis %4 in Schritten von %5)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 cycles cannot be set here (%2 to %3)</source>
        <translation>%1 Zyklen lassen sich hier nicht einstellen (%2 bis %3)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>2. Motion (set by the plan)</source>
        <translation>2. Bewegung (vom Plan gesetzt)</translation>
    </message>
    <message>
        <location line="+151"/>
        <source>Withdraw (recorded)</source>
        <translation>Rückzug (aufgezeichnet)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>RECORDING %1, %2 s</source>
        <translation>AUFZEICHNUNG %1, %2 s</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>no limit</source>
        <translation>keine Grenze</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>Step of one jog</source>
        <translation>Weg eines Tippschritts</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>▲ Out</source>
        <translation>▲ Heraus</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>▼ In</source>
        <translation>▼ Hinein</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Go to position</source>
        <translation>Position anfahren</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Moves the needle without recording</source>
        <translation>Bewegt die Nadel ohne Aufzeichnung</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Moves the needle out to where the last run began (not recorded)</source>
        <translation>Zieht die Nadel bis dorthin zurück, wo der letzte Lauf begann (nicht aufgezeichnet)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The needle is not deeper than where the last run began.</source>
        <translation>Die Nadel steht nicht tiefer als am Beginn des letzten Laufs.</translation>
    </message>
</context>
<context>
    <name>nb::DeviceDialog</name>
    <message>
        <location filename="../widgets/device_dialog.cpp" line="+29"/>
        <source>Devices</source>
        <translation>Geräte</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>serial number, e.g. 360012345</source>
        <translation>Seriennummer, z. B. 360012345</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Analog input (differential with the next one)</source>
        <translation>Analogeingang (differentiell mit dem nächsten)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>×1 (±10 V)</source>
        <translation>×1 (±10 V)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>×10 (±1 V)</source>
        <translation>×10 (±1 V)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>×100 (±100 mV)</source>
        <translation>×100 (±100 mV)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>×1000 (±10 mV)</source>
        <translation>×1000 (±10 mV)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>serial port, e.g. /dev/ttyUSB0</source>
        <translation>serielle Schnittstelle, z. B. /dev/ttyUSB0</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The axis&apos;s micro-steps per millimetre (from its data sheet)</source>
        <translation>Mikroschritte der Achse je Millimeter (aus ihrem Datenblatt)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Force sensor (DAQ)</source>
        <translation>Kraftsensor (Messwerterfassung)</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+6"/>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>Serial number</source>
        <translation>Seriennummer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Input</source>
        <translation>Eingang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Range</source>
        <translation>Messbereich</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Insertion stage</source>
        <translation>Einstichachse</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Port</source>
        <translation>Schnittstelle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Micro-steps per mm</source>
        <translation>Mikroschritte je mm</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Rescan</source>
        <translation>&amp;Neu suchen</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Simulated rig</source>
        <translation>Simulierter Versuchsstand</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>LabJack U6, the first found</source>
        <translation>LabJack U6, der erste gefundene</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Simulated stage</source>
        <translation>Simulierte Achse</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Zaber on %1</source>
        <translation>Zaber an %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>LabJack U6 by serial number…</source>
        <translation>LabJack U6 nach Seriennummer…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zaber on another port…</source>
        <translation>Zaber an anderer Schnittstelle…</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>Found %n LabJack U6(s)</source>
        <translation>
            <numerusform>%n LabJack U6 gefunden</numerusform>
            <numerusform>%n LabJack U6 gefunden</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+0"/>
        <source>%n serial port(s)</source>
        <translation>
            <numerusform>%n serielle Schnittstelle</numerusform>
            <numerusform>%n serielle Schnittstellen</numerusform>
        </translation>
    </message>
    <message>
        <location line="+55"/>
        <source>Type the U6&apos;s serial number, or choose a listed one.</source>
        <translation>Geben Sie die Seriennummer des U6 ein oder wählen Sie einen aufgeführten.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Type the stage&apos;s serial port (zaber:PORT), or choose a listed one.</source>
        <translation>Geben Sie die serielle Schnittstelle der Achse ein (zaber:PORT) oder wählen Sie eine aufgeführte.</translation>
    </message>
</context>
<context>
    <name>nb::ExportDialog</name>
    <message>
        <location filename="../widgets/export_dialog.cpp" line="+57"/>
        <source>Export session</source>
        <translation>Sitzung exportieren</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Choose…</source>
        <translation>Wählen…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export into</source>
        <translation>Exportieren nach</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>CSV per run, with JSON sidecar and label intervals</source>
        <translation>CSV je Lauf, mit JSON-Begleitdatei und Label-Intervallen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>HDF5: the whole session in one file</source>
        <translation>HDF5: die ganze Sitzung in einer Datei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ELAN documents (.eaf) linking force and video</source>
        <translation>ELAN-Dokumente (.eaf), die Kraft und Video verknüpfen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Analysis figures (PNG and PDF)</source>
        <translation>Abbildungen der Auswertung (PNG und PDF)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Analysis tables (CSV and LaTeX)</source>
        <translation>Tabellen der Auswertung (CSV und LaTeX)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Export</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Session</source>
        <translation>Sitzung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Into folder</source>
        <translation>In den Ordner</translation>
    </message>
    <message>
        <location line="+76"/>
        <source>Choose a folder to export into.</source>
        <translation>Einen Zielordner für den Export wählen.</translation>
    </message>
    <message numerus="yes">
        <location line="+28"/>
        <source>%1 already holds an earlier export: %n file(s) will be replaced.</source>
        <translation>
            <numerusform>%1 enthält bereits einen früheren Export: %n Datei wird ersetzt.</numerusform>
            <numerusform>%1 enthält bereits einen früheren Export: %n Dateien werden ersetzt.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n file(s) in %1 are not an earlier export&apos;s (a recorded run, a table made by hand?) and would be replaced and lost.</source>
        <translation>
            <numerusform>%n Datei in %1 stammt nicht aus einem früheren Export (eine aufgezeichnete Messung, eine von Hand erstellte Tabelle?) und würde ersetzt und ginge verloren.</numerusform>
            <numerusform>%n Dateien in %1 stammen nicht aus einem früheren Export (aufgezeichnete Messungen, von Hand erstellte Tabellen?) und würden ersetzt und gingen verloren.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Choose another folder unless you are sure.</source>
        <translation>Wählen Sie einen anderen Ordner, wenn Sie nicht sicher sind.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Replace</source>
        <translation>Ersetzen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Not exported: the files in %1 are kept.</source>
        <translation>Nicht exportiert: die Dateien in %1 bleiben erhalten.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: cannot create the folder</source>
        <translation>%1: der Ordner kann nicht angelegt werden</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Exporting…</source>
        <translation>Exportiere…</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Cancelling…</source>
        <translation>Wird abgebrochen…</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>%1: no runs to export</source>
        <translation>%1: keine Läufe zum Exportieren</translation>
    </message>
    <message>
        <location line="+97"/>
        <source>Cancelled: the earlier export in %1 is as it was.</source>
        <translation>Abgebrochen: der frühere Export in %1 ist unverändert.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cancelled: the files finished before (%1) are kept; none is half written.</source>
        <translation>Abgebrochen: die zuvor fertigen Dateien (%1) bleiben; keine ist halb geschrieben.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export failed: %1. The earlier export in %2 is as it was.</source>
        <translation>Export fehlgeschlagen: %1. Der frühere Export in %2 ist unverändert.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export failed: %1</source>
        <translation>Export fehlgeschlagen: %1</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>Exported %n file(s) into %1</source>
        <translation>
            <numerusform>%n Datei nach %1 exportiert</numerusform>
            <numerusform>%n Dateien nach %1 exportiert</numerusform>
        </translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
</context>
<context>
    <name>nb::ForcePlots</name>
    <message>
        <location filename="../widgets/force_plots.cpp" line="+61"/>
        <location line="+1"/>
        <source>time [s]</source>
        <translation>Zeit [s]</translation>
    </message>
    <message>
        <location line="-1"/>
        <location line="+2"/>
        <source>force [N]</source>
        <translation>Kraft [N]</translation>
    </message>
    <message>
        <location line="-1"/>
        <location line="+1"/>
        <source>position [mm]</source>
        <translation>Position [mm]</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>force</source>
        <translation>Kraft</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>position</source>
        <translation>Position</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>force vs position</source>
        <translation>Kraft über Position</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Follow</source>
        <translation>Mitlaufen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Keep the newest samples in view (zooming or dragging a plot turns this off)</source>
        <translation>Die neuesten Messwerte im Blick behalten (Zoomen oder Verschieben eines Diagramms schaltet das ab)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Pause display</source>
        <translation>Anzeige anhalten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Freeze the plots to look closely; recording goes on and nothing is lost</source>
        <translation>Diagramme anhalten, um genau hinzusehen; die Aufzeichnung läuft weiter, nichts geht verloren</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Show whole run</source>
        <translation>Ganzen Lauf zeigen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zoom out to every sample of the run</source>
        <translation>Herauszoomen auf alle Messwerte des Laufs</translation>
    </message>
    <message>
        <location line="+90"/>
        <source>contact</source>
        <translation>Kontakt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>puncture</source>
        <translation>Durchstich</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>withdraw</source>
        <translation>Zurückziehen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>E-STOP</source>
        <translation>NOT-HALT</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fault</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>force limit</source>
        <translation>Kraftgrenze</translation>
    </message>
    <message>
        <location line="+165"/>
        <source>limit %1 N%2 · margin %3 N</source>
        <translation>Grenze %1 N%2 · Abstand %3 N</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> (above the plot)</source>
        <translation> (oberhalb des Diagramms)</translation>
    </message>
</context>
<context>
    <name>nb::LabelModel</name>
    <message>
        <location filename="../widgets/label_model.cpp" line="+90"/>
        <source>track</source>
        <translation>Spur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>label</source>
        <translation>Label</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>start [s]</source>
        <translation>Beginn [s]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>end [s]</source>
        <translation>Ende [s]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>comment</source>
        <translation>Kommentar</translation>
    </message>
</context>
<context>
    <name>nb::LabelSetDialog</name>
    <message>
        <location filename="../widgets/label_set_dialog.cpp" line="+23"/>
        <source>Label set: %1</source>
        <translation>Label-Satz: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>track</source>
        <translation>Spur</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>label</source>
        <translation>Label</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>hotkey</source>
        <translation>Taste</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Add label</source>
        <translation>Label hinzufügen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>new label</source>
        <translation>neues Label</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Remove label</source>
        <translation>Label entfernen</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Renaming a label does not rename the labels already placed.</source>
        <translation>Das Umbenennen eines Labels benennt bereits gesetzte Labels nicht um.</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>interval</source>
        <translation>Intervall</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>point</source>
        <translation>Punkt</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>one frame back</source>
        <translation>ein Bild zurück</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>one frame forward</source>
        <translation>ein Bild vor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>play / pause</source>
        <translation>Wiedergabe / Pause</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>split</source>
        <translation>teilen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>delete</source>
        <translation>löschen</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Row %1: a label needs a track and a name.</source>
        <translation>Zeile %1: Ein Label braucht eine Spur und einen Namen.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: the hotkey must be one key without Ctrl, Shift or Alt.</source>
        <translation>%1: Die Taste muss eine einzelne Taste ohne Strg, Umschalt oder Alt sein.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: the key %2 already means “%3” in the review workspace.</source>
        <translation>%1: Die Taste %2 bedeutet in der Sichtung bereits „%3“.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 is in the set twice.</source>
        <translation>%1 ist zweimal im Satz.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The key %1 is given to both %2/%3 and %4.</source>
        <translation>Die Taste %1 ist sowohl %2/%3 als auch %4 zugewiesen.</translation>
    </message>
</context>
<context>
    <name>nb::MainWindow</name>
    <message>
        <location filename="../app/main_window.cpp" line="+71"/>
        <source>NeedleBench</source>
        <translation>NeedleBench</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>&amp;Record</source>
        <translation>Aufnah&amp;me</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Analysis</source>
        <translation>Ana&amp;lyse</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Control panel</source>
        <translation>Bedienfeld</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Session</source>
        <translation>Sitzung</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Could not open the configured devices (%1); using the simulated rig.</source>
        <translation>Die eingestellten Geräte konnten nicht geöffnet werden (%1); der simulierte Versuchsstand wird verwendet.</translation>
    </message>
    <message>
        <location filename="../app/main_window_safety.cpp" line="+49"/>
        <source>Emergency stop reset: the stage is enabled again.</source>
        <translation>Not-Halt zurückgesetzt: Die Achse ist wieder eingeschaltet.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Withdrawing to the start position, %1 mm (not recorded)</source>
        <translation>Zurückziehen zur Startposition, %1 mm (nicht aufgezeichnet)</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>Emergency stop: the stage is disabled until you reset it in the control panel.</source>
        <translation>Not-Halt: Die Achse bleibt ausgeschaltet, bis Sie ihn im Bedienfeld zurücksetzen.</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="+591"/>
        <location filename="../app/main_window_safety.cpp" line="+15"/>
        <location line="+31"/>
        <location line="+19"/>
        <source>Not now: %1</source>
        <translation>Jetzt nicht: %1</translation>
    </message>
    <message>
        <location filename="../app/main_window_safety.cpp" line="-37"/>
        <source>Do it anyway only if you are sure the needle is free and at rest.</source>
        <translation>Nur dann trotzdem, wenn Sie sicher sind, dass die Nadel frei ist und ruht.</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Bias force sensor</source>
        <translation>Kraftsensor tarieren</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Bias &amp;anyway</source>
        <translation>&amp;Trotzdem tarieren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Bias taken under load on purpose: %1</source>
        <translation>Bewusst unter Last tariert: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Bias not taken: %1</source>
        <translation>Nicht tariert: %1</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Zero position</source>
        <translation>Position nullen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Zero &amp;anyway</source>
        <translation>&amp;Trotzdem nullen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Position zeroed in tissue on purpose: %1</source>
        <translation>Position bewusst im Gewebe genullt: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Position not zeroed: %1</source>
        <translation>Position nicht genullt: %1</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Simulated rig of this session: %1, seed %2</source>
        <translation>Simulierter Versuchsstand dieser Sitzung: %1, Seed %2</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Simulated rig: %1, seed %2, %3 Hz</source>
        <translation>Simulierter Versuchsstand: %1, Startwert %2, %3 Hz</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="-484"/>
        <source>Recording %1</source>
        <translation>Zeichne %1 auf</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Run not started</source>
        <translation>Lauf nicht gestartet</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Fault: %1: %2</source>
        <translation>Fehler: %1: %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Force limit tripped at %1 N, %2 mm: the stage was stopped</source>
        <translation>Kraftgrenze bei %1 N, %2 mm ausgelöst: die Achse wurde angehalten</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Devices not changed: close the calibration wizard first.</source>
        <translation>Geräte nicht gewechselt: schließen Sie zuerst den Kalibrierassistenten.</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Could not open the chosen devices (%1); using the simulated rig.</source>
        <translation>Die gewählten Geräte ließen sich nicht öffnen (%1); der simulierte Versuchsstand wird verwendet.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Devices: %1</source>
        <translation>Geräte: %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>&amp;Session</source>
        <translation>&amp;Sitzung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;New session…</source>
        <translation>&amp;Neue Sitzung…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Open session…</source>
        <translation>Sitzung ö&amp;ffnen…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Session &amp;details…</source>
        <translation>Sitzungs&amp;details…</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Devices</source>
        <translation>&amp;Geräte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Choose devices…</source>
        <translation>Geräte &amp;wählen…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Simulated rig…</source>
        <translation>&amp;Simulierter Versuchsstand…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Calibration</source>
        <translation>&amp;Kalibrierung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Calibrate force sensor…</source>
        <translation>Kraftsensor &amp;kalibrieren…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Use the sensor&apos;s &amp;nominal calibration</source>
        <translation>&amp;Nennkalibrierung des Sensors verwenden</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>These devices do not state a nominal calibration: calibrate the sensor.</source>
        <translation>Diese Geräte nennen keine Nennkalibrierung: Kalibrieren Sie den Sensor.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Language</source>
        <translation>Sprache</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The language changes when NeedleBench is started again.</source>
        <translation>Die Sprache wechselt beim nächsten Start von NeedleBench.</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Interrupted runs</source>
        <translation>Unterbrochene Läufe</translation>
    </message>
    <message>
        <location line="-3"/>
        <source>Could not recover:
%1</source>
        <translation>Konnte nicht wiederhergestellt werden:
%1</translation>
    </message>
    <message numerus="yes">
        <location line="-4"/>
        <source>Recovered %n interrupted run(s): %1. Each ends where its recording stopped; its file says &apos;end_reason: recovered&apos;.</source>
        <translation>
            <numerusform>%n unterbrochener Lauf wiederhergestellt: %1. Er endet, wo seine Aufzeichnung abbrach; seine Datei sagt &apos;end_reason: recovered&apos;.</numerusform>
            <numerusform>%n unterbrochene Läufe wiederhergestellt: %1. Jeder endet, wo seine Aufzeichnung abbrach; seine Datei sagt &apos;end_reason: recovered&apos;.</numerusform>
        </translation>
    </message>
    <message>
        <location line="-17"/>
        <location line="+30"/>
        <source>Open session</source>
        <translation>Sitzung öffnen</translation>
    </message>
    <message>
        <location line="-29"/>
        <source>%1 is open in another NeedleBench (%2). Close it there first, or open another session.</source>
        <translation>%1 ist in einem anderen NeedleBench offen (%2). Dort zuerst schließen oder eine andere Sitzung öffnen.</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Session %1 open</source>
        <translation>Sitzung %1 geöffnet</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>NeedleBench – %1</source>
        <translation>NeedleBench – %1</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>New session</source>
        <translation>Neue Sitzung</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>The last session, %1, is not there any more (moved or renamed?): open it where it is now, or start a new one.</source>
        <translation>Die letzte Sitzung, %1, ist nicht mehr da (verschoben oder umbenannt?): öffnen Sie sie dort, wo sie jetzt liegt, oder beginnen Sie eine neue.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>No session open: start a new one or open one (Session menu).</source>
        <translation>Keine Sitzung offen: eine neue beginnen oder eine öffnen (Menü Sitzung).</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>The run in review when NeedleBench closed is gone: %1</source>
        <translation>Der beim Beenden von NeedleBench geprüfte Lauf ist nicht mehr da: %1</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Open &amp;video for the run in review…</source>
        <translation>&amp;Video zum Lauf in der Sichtung öffnen…</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Export session…</source>
        <translation>Sitzung &amp;exportieren…</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Open a session to export it.</source>
        <translation>Zum Exportieren eine Sitzung öffnen.</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Session exported into %1</source>
        <translation>Sitzung nach %1 exportiert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export not finished: %1</source>
        <translation>Export nicht abgeschlossen: %1</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>Session details</source>
        <translation>Sitzungsdetails</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Session details saved; the next runs carry them.</source>
        <translation>Sitzungsdetails gespeichert; die nächsten Läufe tragen sie.</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Open session folder</source>
        <translation>Sitzungsordner öffnen</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>Calibration %1 saved in the session and used for every following run (d = %2 mV/g, r² = %3)</source>
        <translation>Kalibrierung %1 in der Sitzung gespeichert und für alle folgenden Läufe verwendet (d = %2 mV/g, r² = %3)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Calibration</source>
        <translation>Kalibrierung</translation>
    </message>
    <message>
        <location line="+63"/>
        <source>Nothing moves or records now. Quit?</source>
        <translation>Nichts bewegt sich oder zeichnet jetzt auf. Beenden?</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Run saved: %1 (%2, %3 samples, %4 dropped)</source>
        <translation>Lauf gespeichert: %1 (%2, %3 Messwerte, %4 verloren)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Run stopped, file incomplete: %1 (%2, %3 samples, %4 dropped)</source>
        <translation>Lauf angehalten, Datei unvollständig: %1 (%2, %3 Messwerte, %4 verloren)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Run file incomplete</source>
        <translation>Laufdatei unvollständig</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 could not be written to the end, and the stage was stopped: %2

The rows written before are kept in the file. Free space on the disk (or choose another session folder) before the next run.</source>
        <translation>%1 konnte nicht bis zum Ende geschrieben werden, und die Achse wurde angehalten: %2

Die zuvor geschriebenen Zeilen bleiben in der Datei. Vor dem nächsten Lauf Platz auf dem Datenträger schaffen (oder einen anderen Sitzungsordner wählen).</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Could not read the run back to mark its events: %1</source>
        <translation>Die Messung konnte zum Markieren ihrer Ereignisse nicht gelesen werden: %1</translation>
    </message>
    <message>
        <location line="+74"/>
        <source>%1
Stop the stage now (emergency stop; the run is saved as such) and quit?</source>
        <translation>%1
Achse jetzt anhalten (Not-Halt; der Lauf wird so gespeichert) und beenden?</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1
Stop the stage now (emergency stop) and quit?</source>
        <translation>%1
Achse jetzt anhalten (Not-Halt) und beenden?</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The needle is still in the tissue. Withdraw it first, or quit and leave it there?</source>
        <translation>Die Nadel steckt noch im Gewebe. Zuerst zurückziehen oder beenden und sie dort lassen?</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The needle is %1 mm from its start. Withdraw it first, or quit and leave it there?</source>
        <translation>Die Nadel steht %1 mm von ihrem Start entfernt. Zuerst zurückziehen oder beenden und sie dort lassen?</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A force of %1 N is on the needle: it may be in the tissue. Withdraw it first, or quit and leave it there?</source>
        <translation>Auf der Nadel liegt eine Kraft von %1 N: sie steckt vielleicht im Gewebe. Zuerst zurückziehen oder beenden und sie dort lassen?</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Don&apos;t quit</source>
        <translation>Nicht beenden</translation>
    </message>
    <message>
        <location line="-835"/>
        <source>Revie&amp;w</source>
        <translation>Sic&amp;htung</translation>
    </message>
    <message>
        <location line="+661"/>
        <source>%1 · %2 Hz · %3 samples · dropped %4</source>
        <translation>%1 · %2 Hz · %3 Messwerte · %4 verloren</translation>
    </message>
    <message numerus="yes">
        <location line="+13"/>
        <source>%1
%n plot frame(s) drawn</source>
        <translation>
            <numerusform>%1
%n Diagrammbild gezeichnet</numerusform>
            <numerusform>%1
%n Diagrammbilder gezeichnet</numerusform>
        </translation>
    </message>
    <message>
        <location line="+157"/>
        <location line="+3"/>
        <source>Quit</source>
        <translation>Beenden</translation>
    </message>
    <message>
        <location line="-598"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../app/main_window_plan.cpp" line="+38"/>
        <source>pending</source>
        <translation>ausstehend</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>again: %1</source>
        <translation>erneut: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>again (%1)</source>
        <translation>erneut (%1)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>running</source>
        <translation>läuft</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>done</source>
        <translation>erledigt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>skipped: %1</source>
        <translation>übersprungen: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>redone</source>
        <translation>wiederholt</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>sine ±%1 mm at %2 Hz, %3 cycles</source>
        <translation>Sinus ±%1 mm bei %2 Hz, %3 Zyklen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>linear to %1 mm at %2 mm/s</source>
        <translation>linear bis %1 mm mit %2 mm/s</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>seed %1</source>
        <translation>Seed %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>stop at the first puncture</source>
        <translation>Halt bei der ersten Punktion</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>stop after %1 punctures</source>
        <translation>Halt nach %1 Punktionen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>slow to %1 mm/s after a puncture</source>
        <translation>nach einer Punktion auf %1 mm/s verlangsamen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>force limit %1 N</source>
        <translation>Kraftgrenze %1 N</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 (from the template %2)</source>
        <translation>%1 (aus der Vorlage %2)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Plan</source>
        <translation>Plan</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Plan run %1 skipped: %2</source>
        <translation>Planlauf %1 übersprungen: %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Plan run %1 is made again: %2</source>
        <translation>Planlauf %1 wird wiederholt: %2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Left the plan: the control panel is yours; runs made now are not the plan&apos;s.</source>
        <translation>Plan verlassen: Das Bedienfeld ist frei; Läufe von jetzt an gehören nicht zum Plan.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>New &amp;plan from template…</source>
        <translation>Neuer &amp;Plan aus Vorlage…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open plan &amp;file…</source>
        <translation>Pl&amp;andatei öffnen…</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+7"/>
        <source>Open plan file</source>
        <translation>Plandatei öffnen</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>Plans (*.json)</source>
        <translation>Pläne (*.json)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Open a session first: the plan is kept in it.</source>
        <translation>Zuerst eine Sitzung öffnen: Der Plan wird darin gespeichert.</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>New plan</source>
        <translation>Neuer Plan</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Experiment plan</source>
        <translation>Versuchsplan</translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>Plan &quot;%1&quot;: %n run(s), kept in %2</source>
        <translation>
            <numerusform>Plan „%1“: %n Lauf, gespeichert in %2</numerusform>
            <numerusform>Plan „%1“: %n Läufe, gespeichert in %2</numerusform>
        </translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The session&apos;s plan could not be opened: %1</source>
        <translation>Der Plan der Sitzung konnte nicht geöffnet werden: %1</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Set by plan run %1 (%2); Leave plan in the Plan dock frees it.</source>
        <translation>Vom Planlauf %1 (%2) gesetzt; „Plan verlassen“ im Plan-Fenster gibt es frei.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Plan run %1 cannot be set: %2. Left the plan.</source>
        <translation>Planlauf %1 lässt sich nicht einstellen: %2. Plan verlassen.</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Plan run %1: %2</source>
        <translation>Planlauf %1: %2</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Simulated rig for plan run %1: %2, seed %3 (enable, bias and zero again)</source>
        <translation>Simulierter Versuchsstand für Planlauf %1: %2, Seed %3 (Achse erneut einschalten, tarieren und Position nullen)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Run %1: %2</source>
        <translation>Lauf %1: %2</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1. %2 – %3</source>
        <translation>%1. %2 – %3</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>run %1 (%2)</source>
        <translation>Lauf %1 (%2)</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Plan run %1 could not be recorded in plan.json: %2</source>
        <translation>Planlauf %1 konnte nicht in plan.json vermerkt werden: %2</translation>
    </message>
</context>
<context>
    <name>nb::NewPlanDialog</name>
    <message>
        <location filename="../widgets/plan_panel.cpp" line="+211"/>
        <source>New plan from template</source>
        <translation>Neuer Plan aus Vorlage</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>as listed</source>
        <translation>wie aufgeführt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>randomised</source>
        <translation>zufällig</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>blocked by site</source>
        <translation>in Blöcken nach Stelle</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Recorded in the plan: the same seed gives the same order</source>
        <translation>Im Plan vermerkt: derselbe Seed ergibt dieselbe Reihenfolge</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Template</source>
        <translation>Vorlage</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Order</source>
        <translation>Reihenfolge</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Seed</source>
        <translation>Seed</translation>
    </message>
</context>
<context>
    <name>nb::PlanPanel</name>
    <message>
        <location line="-206"/>
        <source>No experiment plan in this session. Session ▸ New plan from template… makes one; its runs are then set here one after the other.</source>
        <translation>Kein Versuchsplan in dieser Sitzung. Sitzung ▸ Neuer Plan aus Vorlage… legt einen an; seine Läufe werden dann hier nacheinander eingestellt.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>New plan from template…</source>
        <translation>Neuer Plan aus Vorlage…</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>Bias done</source>
        <translation>Tariert</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ticks itself when the sensor has been biased since the last run</source>
        <translation>Hakt sich selbst ab, sobald der Sensor seit dem letzten Lauf abgeglichen wurde</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zero done</source>
        <translation>Nullposition erledigt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ticks itself when the position has been zeroed since the last run</source>
        <translation>Hakt sich selbst ab, sobald die Position seit dem letzten Lauf genullt wurde</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Done:</source>
        <translation>Erledigt:</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Skip run…</source>
        <translation>Lauf überspringen…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Marks the next run skipped, with a reason, and moves on</source>
        <translation>Markiert den nächsten Lauf mit Grund als übersprungen und geht weiter</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Redo run…</source>
        <translation>Lauf wiederholen…</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Skip run</source>
        <translation>Lauf überspringen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Why is %1 skipped?</source>
        <translation>Warum wird %1 übersprungen?</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Redo run</source>
        <translation>Lauf wiederholen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Why is %1 made again? Its attempt stays in the plan, marked discarded.</source>
        <translation>Warum wird %1 wiederholt? Der Versuch bleibt im Plan, als verworfen markiert.</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Every run of the plan is completed.</source>
        <translation>Alle Läufe des Plans sind abgeschlossen.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Next: %1</source>
        <translation>Als Nächstes: %1</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>No run of the plan is done yet</source>
        <translation>Noch kein Lauf des Plans erledigt</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Makes %1 again, with a reason</source>
        <translation>Wiederholt %1, mit Grund</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Leave plan</source>
        <translation>Plan verlassen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Return to plan</source>
        <translation>Zurück zum Plan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Releases the control panel&apos;s settings; runs made meanwhile are not the plan&apos;s</source>
        <translation>Gibt die Einstellungen des Bedienfelds frei; Läufe in der Zwischenzeit gehören nicht zum Plan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sets and locks the next plan run&apos;s settings again</source>
        <translation>Stellt die Einstellungen des nächsten Planlaufs wieder ein und sperrt sie</translation>
    </message>
</context>
<context>
    <name>nb::PlanReasonDialog</name>
    <message>
        <location line="+36"/>
        <source>e.g. a vessel at this site</source>
        <translation>z. B. ein Gefäß an dieser Stelle</translation>
    </message>
</context>
<context>
    <name>nb::PlanWalker</name>
    <message>
        <location filename="../app/plan_walker.cpp" line="+27"/>
        <source>Plan run %1 had ended before the interruption (%2).</source>
        <translation>Planlauf %1 war vor der Unterbrechung beendet (%2).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Plan run %1 was interrupted; it runs again.</source>
        <translation>Planlauf %1 wurde unterbrochen; er wird wiederholt.</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Open a session first: the plan is kept in it.</source>
        <translation>Zuerst eine Sitzung öffnen: Der Plan wird darin gespeichert.</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+196"/>
        <location line="+27"/>
        <source>A plan run is recording: end it first.</source>
        <translation>Ein Planlauf zeichnet auf: Zuerst beenden.</translation>
    </message>
    <message>
        <location line="-216"/>
        <source>%1 already holds the plan &quot;%2&quot; with runs made; use another session for a new plan.</source>
        <translation>%1 enthält bereits den Plan „%2“ mit durchgeführten Läufen; für einen neuen Plan eine andere Sitzung verwenden.</translation>
    </message>
    <message>
        <location line="+117"/>
        <source>the operator&apos;s step</source>
        <translation>der Handgriff</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bias</source>
        <translation>Tarieren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>zero</source>
        <translation>Nullposition</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Plan run %1: tick the checklist first (%2).</source>
        <translation>Planlauf %1: Zuerst die Checkliste abhaken (%2).</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>No plan</source>
        <translation>Kein Plan</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>All %1 runs completed</source>
        <translation>Alle %1 Läufe abgeschlossen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>less than a minute left</source>
        <translation>weniger als eine Minute übrig</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>about %1 min left</source>
        <translation>noch etwa %1 min</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run %1 of %2 · %3</source>
        <translation>Lauf %1 von %2 · %3</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+44"/>
        <source>No plan run is next.</source>
        <translation>Kein Planlauf steht an.</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+27"/>
        <source>Give a reason.</source>
        <translation>Einen Grund angeben.</translation>
    </message>
</context>
<context>
    <name>nb::ReviewWorkspace</name>
    <message>
        <location filename="../widgets/review_workspace.cpp" line="+101"/>
        <source>Indexing the video: %1 of %2 frames</source>
        <translation>Video wird indiziert: %1 von %2 Bildern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Indexing the video: %1 frames</source>
        <translation>Video wird indiziert: %1 Bilder</translation>
    </message>
    <message>
        <location line="+738"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="-709"/>
        <source>%1 (not attached: the run keeps the video it had)</source>
        <translation>%1 (nicht zugeordnet: der Lauf behält sein bisheriges Video)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>decoded across a damaged stretch: partly made up by the decoder</source>
        <translation>über eine beschädigte Strecke hinweg dekodiert: teils vom Decoder ergänzt</translation>
    </message>
    <message>
        <location line="+1135"/>
        <source>Low confidence: the video&apos;s coder shows this slow needle late, by %1 ms give or take %2 ms; check the offset on an event (contact or puncture) before accepting</source>
        <translation>Geringe Konfidenz: Der Kodierer des Videos zeigt diese langsame Nadel verspätet, um %1 ms, auf ±%2 ms genau; den Versatz vor dem Übernehmen an einem Ereignis (Kontakt oder Durchstich) prüfen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Low confidence: if the needle is faint or burnt-in text lies on its line, draw the line on the video with Shift+drag (shaft to tip) and a region around its path with a drag, then Auto sync again</source>
        <translation>Geringe Konfidenz: ist die Nadel schwach zu sehen oder liegt eingeblendeter Text auf ihrer Linie, die Linie mit Umschalt+Ziehen auf dem Video zeichnen (Schaft zur Spitze) und mit Ziehen einen Bereich um ihren Weg, dann erneut automatisch synchronisieren</translation>
    </message>
    <message>
        <location line="-1103"/>
        <source>Automatic sync failed: %1</source>
        <translation>Automatische Synchronisierung fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Suggestion stopped: the run or its video changed</source>
        <translation>Vorschlag abgebrochen: der Lauf oder sein Video hat sich geändert</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Suggestion dropped: the video&apos;s offset changed while it was read; suggest again</source>
        <translation>Vorschlag verworfen: der Versatz des Videos änderte sich, während es gelesen wurde; erneut vorschlagen</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>force and position only (%1: %2)</source>
        <translation>Kraft und Position allein (%1: %2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>force, position and the tissue&apos;s motion in %1</source>
        <translation>Kraft, Position und der Bewegung des Gewebes in %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>force and position; no relaxation from %1: %2</source>
        <translation>Kraft und Position; keine Relaxation aus %1: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>force and position, the relaxation from the surface in %1</source>
        <translation>Kraft und Position, die Relaxation aus der Oberfläche in %1</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>recording time [s]</source>
        <translation>Aufzeichnungszeit [s]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>force [N]</source>
        <translation>Kraft [N]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>force</source>
        <translation>Kraft</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>recorded position</source>
        <translation>aufgezeichnete Position</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+1168"/>
        <source>needle tracked in the video</source>
        <translation>im Video verfolgte Nadel</translation>
    </message>
    <message>
        <location line="-1165"/>
        <source>position [mm]</source>
        <translation>Position [mm]</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>−10</source>
        <translation>−10</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>ten frames back (Shift+Left)</source>
        <translation>zehn Bilder zurück (Umschalt+Links)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>−1</source>
        <translation>−1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>one frame back (Left)</source>
        <translation>ein Bild zurück (Links)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+631"/>
        <source>Play</source>
        <translation>Abspielen</translation>
    </message>
    <message>
        <location line="-631"/>
        <source>play / pause (Space)</source>
        <translation>Abspielen / Pause (Leertaste)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>+1</source>
        <translation>+1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>one frame forward (Right)</source>
        <translation>ein Bild vor (Rechts)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>+10</source>
        <translation>+10</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>ten frames forward (Shift+Right)</source>
        <translation>zehn Bilder vor (Umschalt+Rechts)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1×</source>
        <translation>%1×</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+25"/>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location line="-24"/>
        <source>jump to a recording time</source>
        <translation>zu einer Aufzeichnungszeit springen</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>go to</source>
        <translation>gehe zu</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>video offset</source>
        <translation>Videoversatz</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>video time = recording time + offset</source>
        <translation>Videozeit = Aufzeichnungszeit + Versatz</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>set the video offset</source>
        <translation>Video-Versatz setzen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source> ppm</source>
        <translation> ppm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>clock drift of the video against the force record (video runs fast: positive)</source>
        <translation>Taktdrift des Videos gegenüber der Kraftaufzeichnung (Video läuft schneller: positiv)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>set the drift</source>
        <translation>Drift setzen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>drift</source>
        <translation>Drift</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>−1 frame</source>
        <translation>−1 Bild</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+7"/>
        <source>nudge the offset by one frame</source>
        <translation>den Versatz um ein Bild verschieben</translation>
    </message>
    <message>
        <location line="-2"/>
        <location line="+7"/>
        <source>nudge the offset by a frame</source>
        <translation>Versatz um ein Bild verschieben</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>+1 frame</source>
        <translation>+1 Bild</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Mark event in force</source>
        <translation>Ereignis in der Kraft markieren</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>the event is at the cursor in the force record</source>
        <translation>das Ereignis liegt am Cursor in der Kraftaufzeichnung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mark event in video</source>
        <translation>Ereignis im Video markieren</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>the event is in the frame shown</source>
        <translation>das Ereignis ist im gezeigten Bild</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+956"/>
        <source>Auto sync</source>
        <translation>Automatisch synchronisieren</translation>
    </message>
    <message>
        <location line="-944"/>
        <source>coded once</source>
        <translation>einmal kodiert</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>tick when the video is as its camera or console wrote it, never converted (as a lab converts a console&apos;s export to H.264): the coder&apos;s lag on a slow needle, and the offset with it, are then known more closely. Kept with the run&apos;s video.</source>
        <translation>ankreuzen, wenn das Video so vorliegt, wie Kamera oder Konsole es schrieben, nie umgewandelt (wie ein Labor den Export einer Konsole in H.264 umwandelt): Die Verspätung des Kodierers bei einer langsamen Nadel und mit ihr der Versatz sind dann genauer bekannt. Wird mit dem Video des Laufs gespeichert.</translation>
    </message>
    <message>
        <location line="+200"/>
        <source>the labels file could not be copied aside: the next label saved replaces it</source>
        <translation>die Label-Datei konnte nicht beiseitegelegt werden: das nächste gespeicherte Label ersetzt sie</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the labels file as it was is kept in %1</source>
        <translation>die Label-Datei, wie sie war, ist in %1 aufbewahrt</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>labels taken from %1 (not yet saved beside the run)</source>
        <translation>Markierungen aus %1 übernommen (noch nicht neben dem Lauf gespeichert)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>labels kept in %1 are saved beside the run again</source>
        <translation>die in %1 aufbewahrten Markierungen sind wieder neben dem Lauf gespeichert</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>labels kept in %1 cannot be read: %2</source>
        <translation>die in %1 aufbewahrten Markierungen sind nicht lesbar: %2</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 opened: %2 samples, %3 labels read</source>
        <translation>%1 geöffnet: %2 Messwerte, %3 Labels gelesen</translation>
    </message>
    <message>
        <location line="+311"/>
        <source>The cursor (%1 s) is outside the recording (%2 to %3 s): labels and force marks go on the recording</source>
        <translation>Der Cursor (%1 s) liegt außerhalb der Aufzeichnung (%2 bis %3 s): Labels und Kraftmarken gehören auf die Aufzeichnung</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>set the offset and drift from two events</source>
        <translation>Versatz und Drift aus zwei Ereignissen setzen</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>set the offset from an event</source>
        <translation>Versatz aus einem Ereignis setzen</translation>
    </message>
    <message>
        <location line="+99"/>
        <source>Redone: %1</source>
        <translation>Wiederhergestellt: %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Undone: %1</source>
        <translation>Rückgängig gemacht: %1</translation>
    </message>
    <message>
        <location line="+71"/>
        <source>They are kept in %1, and saved beside the run when it is opened again and its folder can be written.</source>
        <translation>Sie werden in %1 aufbewahrt und neben dem Lauf gespeichert, sobald er wieder geöffnet wird und sein Ordner beschreibbar ist.</translation>
    </message>
    <message>
        <location line="+88"/>
        <source>Low confidence: the video&apos;s coder shows this slow needle late, by %1 ms give or take %2 ms, as it may have been converted; if it is as the camera or console coded it, tick “coded once”, else check the offset on an event (contact or puncture) before accepting</source>
        <translation>Geringe Konfidenz: Der Kodierer des Videos zeigt diese langsame Nadel verspätet, um %1 ms, auf ±%2 ms genau, da es umgewandelt sein kann; liegt es so vor, wie Kamera oder Konsole es kodierten, „einmal kodiert“ ankreuzen, sonst den Versatz vor dem Übernehmen an einem Ereignis (Kontakt oder Durchstich) prüfen</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Kept with the video: Auto sync now fits the offset for it at once</source>
        <translation>Beim Video gespeichert: Automatisch synchronisieren passt den Versatz nun sofort dafür an</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Sync fitted again for a video coded once: confidence %1</source>
        <translation>Synchronisation für ein einmal kodiertes Video neu angepasst: Konfidenz %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Sync fitted again for a video that may have been converted: confidence %1</source>
        <translation>Synchronisation für ein möglicherweise umgewandeltes Video neu angepasst: Konfidenz %1</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>Automatic sync stopped</source>
        <translation>Automatische Synchronisation abgebrochen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Stop sync</source>
        <translation>Synchronisieren abbrechen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stop the automatic sync (the offset in use stays)</source>
        <translation>die automatische Synchronisation abbrechen (der verwendete Versatz bleibt)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>track the needle and fit its displacement to the recorded position. Drag on the video to draw a region: the needle is read in it alone (leave burnt-in clocks and counters out). Shift+drag from the shaft to the tip to draw the needle&apos;s line where it is not found.</source>
        <translation>die Nadel verfolgen und ihre Verschiebung an die aufgezeichnete Position anpassen. Auf dem Video einen Bereich aufziehen: die Nadel wird nur darin gelesen (eingeblendete Uhren und Zähler außen lassen). Mit Umschalt vom Schaft zur Spitze ziehen, um die Nadellinie zu zeichnen, wo sie nicht gefunden wird.</translation>
    </message>
    <message>
        <location line="+69"/>
        <source>needle tracked (offset found)</source>
        <translation>verfolgte Nadel (gefundener Versatz)</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>accept the sync found</source>
        <translation>gefundene Synchronisation übernehmen</translation>
    </message>
    <message>
        <location line="-1058"/>
        <source>r: correlation of the needle&apos;s tracked displacement with the recorded position at the offset found; confidence also weighs how unique the peak is, whether both halves of the video agree and the motion onsets</source>
        <translation>r: Korrelation der verfolgten Nadelverschiebung mit der aufgezeichneten Position beim gefundenen Versatz; die Konfidenz berücksichtigt auch, wie eindeutig das Maximum ist, ob beide Hälften des Videos übereinstimmen, und die Bewegungsanfänge</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>phases or events from force and position, and from the synchronised video when there is one</source>
        <translation>Phasen oder Ereignisse aus Kraft und Position und, wenn vorhanden, aus dem synchronisierten Video</translation>
    </message>
    <message>
        <location line="+227"/>
        <source>No run open: double-click one in the session list</source>
        <translation>Kein Lauf geöffnet: einen in der Sitzungsliste doppelt anklicken</translation>
    </message>
    <message numerus="yes">
        <location line="+27"/>
        <source>labels: %n</source>
        <translation>
            <numerusform>Labels: %n</numerusform>
            <numerusform>Labels: %n</numerusform>
        </translation>
    </message>
    <message>
        <location line="+36"/>
        <location line="+22"/>
        <source>Open a run first (double-click it in the session list), then attach its video</source>
        <translation>Zuerst einen Lauf öffnen (Doppelklick in der Sitzungsliste), dann sein Video anhängen</translation>
    </message>
    <message>
        <location line="-18"/>
        <source>%1: no such video file</source>
        <translation>%1: keine solche Videodatei</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 attached to %2; sync it (Auto sync, or mark an event in both)</source>
        <translation>%1 an %2 angehängt; jetzt synchronisieren (automatisch, oder ein Ereignis in beiden markieren)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Open the video of %1</source>
        <translation>Video zu %1 öffnen</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Video not attached: %1 is no longer the run in review</source>
        <translation>Video nicht zugeordnet: %1 ist nicht mehr der Lauf in der Sichtung</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>The video of this run, %1, is missing. Open it again where it now lies.</source>
        <translation>Das Video dieses Laufs, %1, fehlt. Bitte dort neu öffnen, wo es jetzt liegt.</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>Video and sync not kept: %1</source>
        <translation>Video und Synchronisation nicht gespeichert: %1</translation>
    </message>
    <message>
        <location line="+230"/>
        <source>%1 on %2 closed at %3 s</source>
        <translation>%1 auf %2 bei %3 s geschlossen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 on %2 was not closed (it would be empty or overlap another phase): not added</source>
        <translation>%1 auf %2 nicht geschlossen (wäre leer oder überlappte eine andere Phase): nicht hinzugefügt</translation>
    </message>
    <message>
        <location line="+106"/>
        <source>They could not be kept elsewhere either (%1): they are lost when another run is opened.</source>
        <translation>Sie ließen sich auch anderswo nicht aufbewahren (%1): Sie gehen verloren, wenn ein anderer Lauf geöffnet wird.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Labels not saved</source>
        <translation>Labels nicht gespeichert</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Labels not saved: %1

%2</source>
        <translation>Labels nicht gespeichert: %1

%2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>force and position (synchronise the video to have its motion used)</source>
        <translation>Kraft und Position (das Video synchronisieren, damit seine Bewegung genutzt wird)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>force and position</source>
        <translation>Kraft und Position</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>force and position (the video is still being indexed)</source>
        <translation>Kraft und Position (das Video wird noch indiziert)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Reading the motion in %1 for the suggestion…</source>
        <translation>Lese die Bewegung in %1 für den Vorschlag…</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Reading the motion in %1 for the suggestion: frame %2 of %3</source>
        <translation>Lese die Bewegung in %1 für den Vorschlag: Bild %2 von %3</translation>
    </message>
    <message numerus="yes">
        <location line="+22"/>
        <source>%n label(s) suggested from %1: check and correct them</source>
        <translation>
            <numerusform>%n Label vorgeschlagen aus %1: prüfen und korrigieren</numerusform>
            <numerusform>%n Labels vorgeschlagen aus %1: prüfen und korrigieren</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>(%n more left out: they overlap labels already there)</source>
        <translation>
            <numerusform>(%n weiteres ausgelassen: es überschneidet vorhandene Labels)</numerusform>
            <numerusform>(%n weitere ausgelassen: sie überschneiden vorhandene Labels)</numerusform>
        </translation>
    </message>
    <message>
        <location line="+130"/>
        <source>correlating: frame %1 of %2…</source>
        <translation>korreliere: Bild %1 von %2…</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>, drift %1 %</source>
        <translation>, Drift %1 %</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>, coded pictures %1 ms late (allowed for)</source>
        <translation>, kodierte Bilder %1 ms verspätet (berücksichtigt)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>LOW CONFIDENCE: %1; check it on an event before accepting</source>
        <translation>GERINGE KONFIDENZ: %1; vor dem Annehmen an einem Ereignis prüfen</translation>
    </message>
    <message>
        <location line="-1026"/>
        <source>Accept</source>
        <translation>Übernehmen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>use the offset found</source>
        <translation>den gefundenen Versatz verwenden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>accept a low confidence</source>
        <translation>geringe Konfidenz akzeptieren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the offset found is below the accept threshold: tick only after checking it on an event in both</source>
        <translation>der gefundene Versatz liegt unter der Annahmeschwelle: erst ankreuzen, nachdem er an einem Ereignis in beiden geprüft wurde</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Reject</source>
        <translation>Verwerfen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>keep the current offset</source>
        <translation>den aktuellen Versatz behalten</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>video offset [s]</source>
        <translation>Videoversatz [s]</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Suggest labels</source>
        <translation>Labels vorschlagen</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Edit label set…</source>
        <translation>Label-Satz bearbeiten…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>add, rename or remove the labels of this protocol and their hotkeys</source>
        <translation>Labels dieses Protokolls und ihre Tasten hinzufügen, umbenennen oder entfernen</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>Keys: %1 · S split · Del delete · Ctrl+Z undo</source>
        <translation>Tasten: %1 · S teilen · Entf löschen · Strg+Z rückgängig</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Label set of %1 saved: %2 labels</source>
        <translation>Label-Satz für %1 gespeichert: %2 Labels</translation>
    </message>
    <message>
        <location line="+165"/>
        <source>Indexing the video…</source>
        <translation>Video wird indiziert…</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>Videos (%1);;All files (*)</source>
        <translation>Videos (%1);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+158"/>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>Event marked in the force record at %1 s; now step the video to it and mark it there</source>
        <translation>Ereignis in der Kraftaufzeichnung bei %1 s markiert; nun das Video dorthin schalten und es dort markieren</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Event marked in the video at %1 s; now mark it in the force record</source>
        <translation>Ereignis im Video bei %1 s markiert; nun in der Kraftaufzeichnung markieren</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Offset and drift set from two events (%1 s apart): drift %2 ppm</source>
        <translation>Versatz und Drift aus zwei Ereignissen gesetzt (%1 s auseinander): Drift %2 ppm</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Offset set. With the event before, it would mean a drift of %1 ppm, which no clock has: check both marks; the drift was kept</source>
        <translation>Versatz gesetzt. Mit dem vorigen Ereignis ergäbe sich eine Drift von %1 ppm, die keine Uhr hat: bitte beide Markierungen prüfen; die Drift wurde beibehalten</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Offset set; mark a second event, a second or more away, in both to set the drift too</source>
        <translation>Versatz gesetzt; ein zweites Ereignis, mindestens eine Sekunde entfernt, in beiden markieren, um auch die Drift zu setzen</translation>
    </message>
    <message>
        <location line="+74"/>
        <source>%1 overlaps another phase on %2: not added</source>
        <translation>%1 überlappt eine andere Phase auf %2: nicht hinzugefügt</translation>
    </message>
    <message>
        <location line="+95"/>
        <source>Labels not saved: %1</source>
        <translation>Labels nicht gespeichert: %1</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>suggest labels</source>
        <translation>Labels vorschlagen</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>Open a run and a video first</source>
        <translation>Zuerst einen Lauf und ein Video öffnen</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>correlating…</source>
        <translation>korreliere…</translation>
    </message>
    <message>
        <location line="+120"/>
        <source>found %1 s (confidence %2, r = %3)</source>
        <translation>%1 s gefunden (Konfidenz %2, r = %3)</translation>
    </message>
</context>
<context>
    <name>nb::RunListModel</name>
    <message>
        <location filename="../widgets/session_view.cpp" line="+42"/>
        <source>recording</source>
        <translation>Aufzeichnung läuft</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>#</source>
        <translation>Nr.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>File</source>
        <translation>Datei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Motion</source>
        <translation>Bewegung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Calibration</source>
        <translation>Kalibrierung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Saved</source>
        <translation>Gespeichert</translation>
    </message>
</context>
<context>
    <name>nb::SessionInfoDialog</name>
    <message>
        <location filename="../widgets/session_info_dialog.cpp" line="+22"/>
        <source>New session</source>
        <translation>Neue Sitzung</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Session details</source>
        <translation>Sitzungsdetails</translation>
    </message>
    <message>
        <location line="+15"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Slab thickness on the friction platform; 0 for a whole organ</source>
        <translation>Dicke der Gewebescheibe auf der Reibungsplattform; 0 für ein ganzes Organ</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>overall stiffness, friction, …</source>
        <translation>Gesamtsteifigkeit, Reibung, …</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Organ</source>
        <translation>Organ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Specimen number</source>
        <translation>Probennummer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Needle tip</source>
        <translation>Nadelspitze</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Thickness</source>
        <translation>Dicke</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Operator</source>
        <translation>Bediener</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Protocol</source>
        <translation>Protokoll</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Notes</source>
        <translation>Notizen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Browse…</source>
        <translation>Durchsuchen…</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+8"/>
        <source>Parent folder</source>
        <translation>Übergeordneter Ordner</translation>
    </message>
</context>
<context>
    <name>nb::SessionView</name>
    <message>
        <location filename="../widgets/session_view.cpp" line="+75"/>
        <source>No session open (Session ▸ New or Open).</source>
        <translation>Keine Sitzung geöffnet (Sitzung ▸ Neu oder Öffnen).</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>specimen %1</source>
        <translation>Probe %1</translation>
    </message>
    <message>
        <location line="-13"/>
        <source>%1 tip</source>
        <translation>Spitze %1</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>beveled tip</source>
        <translation>abgeschrägte Spitze</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>diamond tip</source>
        <translation>Diamantschliff-Spitze</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>blunt tip</source>
        <translation>stumpfe Spitze</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 mm thick</source>
        <translation>%1 mm dick</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>operator %1</source>
        <translation>Bediener %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&lt;b&gt;%1&lt;/b&gt; – %2&lt;br&gt;active calibration: %3</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; – %2&lt;br&gt;aktive Kalibrierung: %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no specimen details</source>
        <translation>keine Angaben zur Probe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>none saved in this session (the sensor&apos;s nominal one is used)</source>
        <translation>keine in dieser Sitzung gespeichert (die Nennkalibrierung des Sensors wird verwendet)</translation>
    </message>
</context>
<context>
    <name>nb::SimulatedRigDialog</name>
    <message>
        <location filename="../widgets/simulated_rig_dialog.cpp" line="+19"/>
        <source>Simulated rig</source>
        <translation>Simulierter Versuchsstand</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the preset&apos;s usual tip</source>
        <translation>die übliche Spitze der Vorlage</translation>
    </message>
    <message>
        <location line="+12"/>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Tissue preset</source>
        <translation>Gewebevorlage</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Needle tip</source>
        <translation>Nadelspitze</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Random seed</source>
        <translation>Zufalls-Startwert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sample rate</source>
        <translation>Abtastrate</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The rig is rebuilt when you press OK; each run&apos;s file records these settings.</source>
        <translation>Der Versuchsstand wird mit OK neu aufgebaut; jede Laufdatei hält diese Einstellungen fest.</translation>
    </message>
</context>
<context>
    <name>nb::TrCli</name>
    <message>
        <location filename="../app/cmd_acquire.cpp" line="+27"/>
        <source>sim | u6 | u6:SERIAL (default: settings, else sim)</source>
        <translation>sim | u6 | u6:SERIENNUMMER (Standard: Einstellungen, sonst sim)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sim | zaber:PORT (default: settings, else sim)</source>
        <translation>sim | zaber:PORT (Standard: Einstellungen, sonst sim)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stiffness|internal|friction|prostate (friction: sine motion)</source>
        <translation>stiffness|internal|friction|prostate (friction: Sinusbewegung)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../app/cmd_simulate.cpp" line="+49"/>
        <source>the run file to write</source>
        <translation>die zu schreibende Laufdatei</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../app/cmd_simulate.cpp" line="-11"/>
        <source>sampling rate, 100..10000 (default 500)</source>
        <translation>Abtastrate, 100..10000 (Standard 500)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>insertion velocity (default 4)</source>
        <translation>Einstichgeschwindigkeit (Standard 4)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../app/cmd_simulate.cpp" line="+2"/>
        <source>insertion depth from the start position (default 40)</source>
        <translation>Einstichtiefe ab der Startposition (Standard 40)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sine amplitude (default 10)</source>
        <translation>Sinusamplitude (Standard 10)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../app/cmd_simulate.cpp" line="+2"/>
        <source>sine frequency (default 0.5)</source>
        <translation>Sinusfrequenz (Standard 0,5)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../app/cmd_simulate.cpp" line="+1"/>
        <source>sine cycles (default 7)</source>
        <translation>Sinuszyklen (Standard 7)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../app/cmd_simulate.cpp" line="+3"/>
        <source>force limit that stops the stage (default 8)</source>
        <translation>Kraftgrenze, bei der die Achse anhält (Standard 8)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stage resolution (default: settings, else 20997.375)</source>
        <translation>Auflösung der Achse (Standard: Einstellungen, sonst 20997.375)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sensor calibration slope d in V/g (default: settings, else nominal)</source>
        <translation>Kalibriersteigung d des Sensors in V/g (Standard: Einstellungen, sonst Nennwert)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../app/cmd_simulate.cpp" line="+5"/>
        <source>stop the insertion at a puncture: puncture (the first) or puncture:N (the N-th)</source>
        <translation>die Insertion bei einer Punktion anhalten: puncture (die erste) oder puncture:N (die N-te)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../app/cmd_simulate.cpp" line="+1"/>
        <source>slow the insertion to V mm/s after the first puncture</source>
        <translation>die Insertion nach der ersten Punktion auf V mm/s verlangsamen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>replace an existing run file</source>
        <translation>eine vorhandene Laufdatei ersetzen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Run &apos;needlebench acquire --help&apos; for the options.</source>
        <translation>&apos;needlebench acquire --help&apos; zeigt die Optionen.</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>--protocol must be one of %1</source>
        <translation>--protocol muss eines von %1 sein</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../app/cmd_simulate.cpp" line="+39"/>
        <source>--out RUN.csv is required</source>
        <translation>--out LAUF.csv ist erforderlich</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>--%1 must be a number in [%2, %3] (got &apos;%4&apos;)</source>
        <translation>--%1 muss eine Zahl in [%2, %3] sein (erhalten: &apos;%4&apos;)</translation>
    </message>
    <message>
        <location line="+57"/>
        <location filename="../app/cmd_simulate.cpp" line="+129"/>
        <source>--stop-at wants puncture or puncture:N with N ≥ 1 (got &apos;%1&apos;)</source>
        <translation>--stop-at erwartet puncture oder puncture:N mit N ≥ 1 (erhalten: „%1“)</translation>
    </message>
    <message>
        <location filename="../app/interrupt_watcher.cpp" line="+112"/>
        <source>%1 received: stopping the stage and closing the run</source>
        <translation>%1 empfangen: Verfahrtisch wird gestoppt und der Lauf abgeschlossen</translation>
    </message>
    <message>
        <location filename="../app/cmd_acquire.cpp" line="+27"/>
        <location filename="../app/cmd_simulate.cpp" line="+102"/>
        <source>recording failed: %1; the run file keeps %2 whole rows</source>
        <translation>Aufzeichnung fehlgeschlagen: %1; die Laufdatei behält %2 vollständige Zeilen</translation>
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
        <translation>JSON ausgeben</translation>
    </message>
    <message>
        <location line="+15"/>
        <location line="+7"/>
        <source>simulated load cell (default)</source>
        <translation>simulierte Kraftmessdose (Standard)</translation>
    </message>
    <message>
        <location line="-5"/>
        <location line="+11"/>
        <source>simulated stage (default)</source>
        <translation>simulierte Achse (Standard)</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>DAQs (--daq):
</source>
        <translation>Messkarten (--daq):
</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Stages (--stage):
</source>
        <translation>Achsen (--stage):
</translation>
    </message>
    <message>
        <location filename="../app/cmd_events.cpp" line="+2"/>
        <source>a constant-velocity insertion run</source>
        <translation>ein Einstichlauf mit konstanter Geschwindigkeit</translation>
    </message>
    <message>
        <location line="+14"/>
        <location filename="../app/cmd_fit.cpp" line="-302"/>
        <location line="+20"/>
        <location filename="../app/cmd_labels.cpp" line="+118"/>
        <location filename="../app/cmd_sync.cpp" line="+66"/>
        <source>warning: %1
</source>
        <translation>Warnung: %1
</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>events of %1 (force zeroed by %2 N, noise %3 N)
</source>
        <translation>Ereignisse von %1 (Kraft um %2 N genullt, Rauschen %3 N)
</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>event                 time_s position_mm   force_N
</source>
        <translation>event                 time_s position_mm   force_N
</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>contact</source>
        <translation>Kontakt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>puncture</source>
        <translation>Durchstich</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>relaxation</source>
        <translation>Relaxation</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>internal puncture</source>
        <translation>innerer Durchstich</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>puncture depth %1 mm; stiffness a1 = %2 N/mm, a2 = %3 N/mm² (as fit stiffness gives it)
</source>
        <translation>Durchstichtiefe %1 mm; Steifigkeit a1 = %2 N/mm, a2 = %3 N/mm² (wie fit stiffness sie gibt)
</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>puncture depth %1 mm; no stiffness fit (%2)
</source>
        <translation>Durchstichtiefe %1 mm; kein Steifigkeitsfit (%2)
</translation>
    </message>
    <message>
        <location filename="../app/cmd_export.cpp" line="+54"/>
        <source>warning: %1: could not copy the video beside the export; linked where it is</source>
        <translation>Warnung: %1: das Video konnte nicht neben den Export kopiert werden; es wird an seinem Ort verknüpft</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Export a session&apos;s runs, labels and metadata.</source>
        <translation>Läufe, Labels und Metadaten einer Sitzung exportieren.</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../app/cmd_plan.cpp" line="+8"/>
        <source>a session folder (or any folder of run files)</source>
        <translation>ein Sitzungsordner (oder ein beliebiger Ordner mit Laufdateien)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>csv: a CSV + JSON sidecar + label interval table per run (OUT is a folder); hdf5: one HDF5 file (OUT is the file); eaf: an ELAN document per run with its force CSV linked (OUT is a folder)</source>
        <translation>csv: je Lauf eine CSV + JSON-Begleitdatei + Label-Intervalltabelle (OUT ist ein Ordner); hdf5: eine HDF5-Datei (OUT ist die Datei); eaf: je Lauf ein ELAN-Dokument mit verknüpfter Kraft-CSV (OUT ist ein Ordner)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>where to write</source>
        <translation>wohin geschrieben wird</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>put each run&apos;s video beside the export (hard link, else copy) and link that, so the export folder can be moved or shared on its own</source>
        <translation>das Video jedes Laufs neben den Export legen (harter Link, sonst Kopie) und dorthin verweisen, damit der Exportordner allein verschoben oder weitergegeben werden kann</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>replace files in OUT that are not an earlier export&apos;s (a run file, a table made by hand); an earlier export&apos;s files are replaced without it</source>
        <translation>Dateien in OUT ersetzen, die nicht aus einem früheren Export stammen (eine Messdatei, eine von Hand erstellte Tabelle); Dateien eines früheren Exports werden auch ohne diese Option ersetzt</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>--format is required (csv|hdf5|eaf)</source>
        <translation>--format ist erforderlich (csv|hdf5|eaf)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>unknown format &apos;%1&apos; (csv|hdf5|eaf)</source>
        <translation>unbekanntes Format &apos;%1&apos; (csv|hdf5|eaf)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+5"/>
        <source>Run &apos;needlebench export --help&apos; for the options.</source>
        <translation>&apos;needlebench export --help&apos; zeigt die Optionen.</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>--out PATH is required</source>
        <translation>--out PFAD ist erforderlich</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>--out %1 is the session folder itself; its run files would be replaced. Name another folder.</source>
        <translation>--out %1 ist der Sitzungsordner selbst; seine Laufdateien würden ersetzt. Geben Sie einen anderen Ordner an.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--out %1 exists and is not an HDF5 file (a run file?); it is kept. Name another file.</source>
        <translation>--out %1 existiert und ist keine HDF5-Datei (eine Laufdatei?); sie bleibt erhalten. Geben Sie eine andere Datei an.</translation>
    </message>
    <message numerus="yes">
        <location line="+80"/>
        <source>the %n file(s) this export had written are removed</source>
        <translation>
            <numerusform>die %n Datei, die dieser Export geschrieben hatte, ist entfernt</numerusform>
            <numerusform>die %n Dateien, die dieser Export geschrieben hatte, sind entfernt</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+79"/>
        <source>%n run(s) of the session left out (named above): %1</source>
        <translation>
            <numerusform>%n Lauf der Sitzung ausgelassen (oben genannt): %1</numerusform>
            <numerusform>%n Läufe der Sitzung ausgelassen (oben genannt): %1</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/cmd_demo.cpp" line="+59"/>
        <source>Simulate, label, fit and export a short session in one go.</source>
        <translation>Eine kurze Sitzung in einem Zug simulieren, markieren, auswerten und exportieren.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the folder to write everything into</source>
        <translation>der Ordner, in den alles geschrieben wird</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a shorter session (one run per condition, fewer cycles)</source>
        <translation>eine kürzere Sitzung (ein Lauf je Bedingung, weniger Zyklen)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>--out DIR is required</source>
        <translation>--out ORDNER ist erforderlich</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Run &apos;needlebench demo --help&apos; for the options.</source>
        <translation>&apos;needlebench demo --help&apos; zeigt die Optionen.</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>session folder %1</source>
        <translation>Sitzungsordner %1</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>simulating %1 failed: %2</source>
        <translation>Simulation von %1 fehlgeschlagen: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>simulated %1 (%2, %3)</source>
        <translation>simuliert %1 (%2, %3)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>sine %1 Hz</source>
        <translation>Sinus %1 Hz</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>insertion 4 mm/s</source>
        <translation>Einstich 4 mm/s</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>rendered imaging video %1 (%2 frames at 29.97/s, started %3 s before the recording)</source>
        <translation>Bildgebungsvideo %1 gerendert (%2 Bilder bei 29,97/s, Beginn %3 s vor der Aufnahme)</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>synchronised %1: offset %2 s found, %3 s true (%4 frames off), confidence %5</source>
        <translation>%1 synchronisiert: Versatz %2 s gefunden, %3 s wahr (%4 Bilder daneben), Konfidenz %5</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>note: could not synchronise %1 (%2); its frames are numbered without an offset</source>
        <translation>Hinweis: %1 konnte nicht synchronisiert werden (%2); die Bilder werden ohne Versatz nummeriert</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>phases a, b1, b2, c per half-cycle, checked against the tissue&apos;s motion in %1</source>
        <translation>Phasen a, b1, b2, c je Halbzyklus, geprüft an der Gewebebewegung in %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>phases a, b1, b2, c per half-cycle from force and position (%1: %2)</source>
        <translation>Phasen a, b1, b2, c je Halbzyklus aus Kraft und Position (%1: %2)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>contact and puncture events; no imaging video to read the relaxation off</source>
        <translation>Ereignisse Kontakt und Durchstich; kein Bildgebungsvideo, um die Relaxation abzulesen</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>labelled %1: %2 suggested labels (%3)</source>
        <translation>%1 beschriftet: %2 vorgeschlagene Labels (%3)</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>phases a, b1, b2, c per half-cycle</source>
        <translation>Phasen a, b1, b2, c je Halbzyklus</translation>
    </message>
    <message>
        <location line="-150"/>
        <source>%1 is not empty; a demo writes a session and its exports into --out: choose an empty or new folder</source>
        <translation>%1 ist nicht leer; eine Demo schreibt eine Sitzung und ihre Exporte in --out: einen leeren oder neuen Ordner wählen</translation>
    </message>
    <message>
        <location line="+165"/>
        <location line="+4"/>
        <location filename="../app/cmd_export.cpp" line="-144"/>
        <source>warning: %1</source>
        <translation>Warnung: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fitted %1 stiffness runs in %2 groups, %3 friction runs, %4 validations</source>
        <translation>%1 Steifigkeitsläufe in %2 Gruppen, %3 Reibungsläufe, %4 Validierungen gefittet</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>wrote %1 run CSVs with JSON sidecars and label interval tables</source>
        <translation>%1 Lauf-CSVs mit JSON-Begleitdateien und Label-Intervalltabellen geschrieben</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>wrote %1</source>
        <translation>%1 geschrieben</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>wrote %1 fit tables (CSV and LaTeX)</source>
        <translation>%1 Fit-Tabellen geschrieben (CSV und LaTeX)</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>wrote %1 figures</source>
        <translation>%1 Abbildungen geschrieben</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Demo finished in %1 s. Where everything went:</source>
        <translation>Demo in %1 s abgeschlossen. Wo alles liegt:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>  session (run files + labels): %1</source>
        <translation>  Sitzung (Laufdateien + Labels): %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>  run CSVs + JSON sidecars:     %1</source>
        <translation>  Lauf-CSVs + JSON-Begleitdateien: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>  HDF5 (all runs):              %1</source>
        <translation>  HDF5 (alle Läufe):             %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>  fit tables (CSV, LaTeX):      %1</source>
        <translation>  Fit-Tabellen (CSV, LaTeX):    %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>  figures (PNG, PDF, SVG):      %1</source>
        <translation>  Abbildungen (PNG, PDF, SVG): %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>  simulator ground truth:       %1</source>
        <translation>  Referenzwerte des Simulators: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>  video %1 (%2 frames): sync offset %3 s found, %4 s true, %5 ms off, confidence %6</source>
        <translation>  Video %1 (%2 Bilder): Synchronisationsversatz %3 s gefunden, %4 s wahr, %5 ms daneben, Konfidenz %6</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>  video %1 (%2 frames): not synchronised (%3); true offset %4 s</source>
        <translation>  Video %1 (%2 Bilder): nicht synchronisiert (%3); wahrer Versatz %4 s</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>  stiffness %1: a1 = %2 N/mm, a2 = %3 N/mm², puncture at %4 mm, %5 N</source>
        <translation>  Steifigkeit %1: a1 = %2 N/mm, a2 = %3 N/mm², Durchstich bei %4 mm, %5 N</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>  friction overall: Cp = %1 N/m, Cn = %2 N/m, bp = %3 N s/m², bn = %4 N s/m²</source>
        <translation>  Reibung gesamt: Cp = %1 N/m, Cn = %2 N/m, bp = %3 N s/m², bn = %4 N s/m²</translation>
    </message>
    <message>
        <location filename="../app/cmd_export.cpp" line="+2"/>
        <source>%1: no run files (*.csv with time_s,position_mm,force_N)</source>
        <translation>%1: keine Laufdateien (*.csv mit time_s,position_mm,force_N)</translation>
    </message>
    <message numerus="yes">
        <location line="+13"/>
        <source>%n file(s) in %1 would be replaced that are not an earlier export&apos;s (%2); they are kept. Name another folder, or give --overwrite.</source>
        <translation>
            <numerusform>%n Datei in %1, die nicht aus einem früheren Export stammt, würde ersetzt (%2); sie bleibt erhalten. Geben Sie einen anderen Ordner an oder --overwrite.</numerusform>
            <numerusform>%n Dateien in %1, die nicht aus einem früheren Export stammen, würden ersetzt (%2); sie bleiben erhalten. Geben Sie einen anderen Ordner an oder --overwrite.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+7"/>
        <source>note: replacing %n file(s) of an earlier export in %1</source>
        <translation>
            <numerusform>Hinweis: %n Datei eines früheren Exports in %1 wird ersetzt</numerusform>
            <numerusform>Hinweis: %n Dateien eines früheren Exports in %1 werden ersetzt</numerusform>
        </translation>
    </message>
    <message>
        <location line="+33"/>
        <source>the earlier export in %1 is as it was</source>
        <translation>der frühere Export in %1 ist unverändert</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>warning: removed %1, left by an export that did not finish</source>
        <translation>Warnung: %1 entfernt, von einem nicht beendeten Export zurückgelassen</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>writing %1 runs to %2</source>
        <translation>schreibe %1 Läufe nach %2</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>cancelled; %1 was not written</source>
        <translation>abgebrochen; %1 wurde nicht geschrieben</translation>
    </message>
    <message>
        <location filename="../app/cmd_demo.cpp" line="-254"/>
        <location filename="../app/cmd_export.cpp" line="-23"/>
        <location line="+11"/>
        <location line="+19"/>
        <source>%1: cannot create the folder</source>
        <translation>%1: Ordner kann nicht angelegt werden</translation>
    </message>
    <message>
        <location filename="../app/cmd_export.cpp" line="+10"/>
        <source>cancelled after %1 of %2 runs; %3 was not written</source>
        <translation>abgebrochen nach %1 von %2 Läufen; %3 wurde nicht geschrieben</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>exported %1 runs from %2 as %3: %4 files</source>
        <translation>%1 Läufe aus %2 als %3 exportiert: %4 Dateien</translation>
    </message>
    <message>
        <location filename="../app/cmd_fit.cpp" line="+2"/>
        <source>warning: %1: %2
</source>
        <translation>Warnung: %1: %2
</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>warning: %1: %2 not used by this fit (it reads %3)
</source>
        <translation>Warnung: %1: %2 wird von dieser Anpassung nicht verwendet (sie liest %3)
</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>warning: %1 is given more than once; it is fitted once</source>
        <translation>Warnung: %1 ist mehrfach angegeben; angepasst wird es einmal</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>%1: the fit gave no finite result (forces or positions out of any measurable range?)</source>
        <translation>%1: die Anpassung ergab kein endliches Ergebnis (Kräfte oder Positionen außerhalb jedes messbaren Bereichs?)</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>calibration points: columns mass_g, voltage_V</source>
        <translation>Kalibrierpunkte: Spalten mass_g, voltage_V</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>calibration %1: V = %2 V/g * m + %3 V   r2 = %4   rms = %5 V
</source>
        <translation>Kalibrierung %1: V = %2 V/g * m + %3 V   r2 = %4   RMS = %5 V
</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>    mass_g   voltage_V  residual_V
</source>
        <translation>    mass_g   voltage_V  residual_V
</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>  &lt;- largest residual, check this point</source>
        <translation>  &lt;- größtes Residuum, diesen Punkt prüfen</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>a run&apos;s labels (track,label,start_s,end_s,comment); its &apos;contact&apos; and &apos;puncture&apos; points replace the detected ones. Give it once per run, in the runs&apos; order.</source>
        <translation>die Markierungen eines Laufs (track,label,start_s,end_s,comment); ihre Punkte „contact“ und „puncture“ ersetzen die erkannten. Einmal je Lauf angeben, in der Reihenfolge der Läufe.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>constant-velocity insertion runs</source>
        <translation>Einstichläufe mit konstanter Geschwindigkeit</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 label files for %2 runs; give --labels once per run, in the runs&apos; order
</source>
        <translation>%1 Markierungsdateien für %2 Läufe; --labels einmal je Lauf angeben, in der Reihenfolge der Läufe
</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Usage: needlebench fit stiffness RUN.csv... [--labels FILE]... [--json]
</source>
        <translation>Aufruf: needlebench fit stiffness LAUF.csv... [--labels DATEI]... [--json]
</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>warning: %1 marks no %2 for %3: found in the force instead</source>
        <translation>Warnung: %1 markiert für %3 kein %2: stattdessen aus der Kraft bestimmt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> or </source>
        <translation> oder </translation>
    </message>
    <message>
        <location line="+51"/>
        <source>stiffness f = a1*x + a2*x^2, x = depth past contact [mm]
</source>
        <translation>Steifigkeit f = a1*x + a2*x^2, x = Tiefe nach dem Kontakt [mm]
</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>run                       contact_mm puncture_mm depth_mm  force_N  a1_N/mm   a2_N/mm2  rms_N    r2
</source>
        <translation>run                       contact_mm puncture_mm depth_mm  force_N  a1_N/mm   a2_N/mm2  rms_N    r2
</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>pooled</source>
        <translation>pooled</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mean of runs: a1 = %1 ± %2 N/mm, a2 = %3 ± %4 N/mm²
</source>
        <translation>Mittel der Läufe: a1 = %1 ± %2 N/mm, a2 = %3 ± %4 N/mm²
</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>alternatives (pooled): cubic rms %1 N r2 %2 (a3 = %3 N/mm³); spring x/(a x + b) rms %4 N r2 %5
</source>
        <translation>Alternativen (gepoolt): kubisch RMS %1 N r2 %2 (a3 = %3 N/mm³); Feder x/(a x + b) RMS %4 N r2 %5
</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>length of needle in tissue (slab thickness), required</source>
        <translation>Länge der Nadel im Gewebe (Dicke der Gewebescheibe), erforderlich</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>needle holder mass removed from the force (eq. 21, default 0.087)</source>
        <translation>aus der Kraft herausgerechnete Masse des Nadelhalters (Gl. 21, Standard 0,087)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>estimate the mass with the friction (eq. 19)</source>
        <translation>die Masse zusammen mit der Reibung schätzen (Gl. 19)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>zero-velocity band width, e.g. 0.005 = ±2.5 mm/s (default: found in each run&apos;s data)</source>
        <translation>Breite des Nullgeschwindigkeitsbands, z. B. 0.005 = ±2,5 mm/s (Standard: aus den Daten jedes Laufs bestimmt)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>phase labels (track,label,start_s,end_s,comment) for a single run; C and b then come from phase c, D from phase a. Runs may carry a &apos;phase&apos; column instead. Without phases the velocity band decides.</source>
        <translation>Phasen-Labels (track,label,start_s,end_s,comment) für einen einzelnen Lauf; C und b kommen dann aus Phase c, D aus Phase a. Läufe können stattdessen eine Spalte &apos;phase&apos; enthalten. Ohne Phasen entscheidet das Geschwindigkeitsband.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the tissue&apos;s velocity over the run (time_s,tissue_velocity_mm_s, as labels suggest --tissue-trace writes it from the video) for a single run: C and b are then fitted against the needle&apos;s velocity relative to the tissue</source>
        <translation>die Geschwindigkeit des Gewebes über den Lauf (time_s,tissue_velocity_mm_s, wie labels suggest --tissue-trace sie aus dem Video schreibt) für einen einzelnen Lauf: C und b werden dann gegen die Geschwindigkeit der Nadel relativ zum Gewebe angepasst</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>sinusoidal runs through a tissue slab</source>
        <translation>sinusförmige Läufe durch eine Gewebescheibe</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>--thickness-mm is required</source>
        <translation>--thickness-mm ist erforderlich</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>--thickness-mm: %1 mm is no slab (at most %2 mm)</source>
        <translation>--thickness-mm: %1 mm ist keine Gewebeplatte (höchstens %2 mm)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>--thickness-mm: &apos;%1&apos; is not a positive number</source>
        <translation>--thickness-mm: &apos;%1&apos; ist keine positive Zahl</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>--mass-kg and --estimate-mass exclude each other</source>
        <translation>--mass-kg und --estimate-mass schließen einander aus</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--mass-kg: &apos;%1&apos; is not a mass</source>
        <translation>--mass-kg: &apos;%1&apos; ist keine Masse</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--band-m-s: &apos;%1&apos; is not a positive number</source>
        <translation>--band-m-s: &apos;%1&apos; ist keine positive Zahl</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>--labels applies to a single run; give one run per call</source>
        <translation>--labels gilt für einen einzelnen Lauf; geben Sie einen Lauf pro Aufruf an</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>warning: %1 holds no friction phase over %2 (a, b1, b2, c); the run&apos;s own phase column is used, else the velocity band</source>
        <translation>Warnung: %1 enthält über %2 keine Reibungsphase (a, b1, b2, c); die eigene Phasenspalte des Laufs wird verwendet, sonst das Geschwindigkeitsband</translation>
    </message>
    <message>
        <location line="+149"/>
        <source>friction per unit length of needle in tissue (thickness %1 mm): C, D in N/m, b in N·s/m²
</source>
        <translation>Reibung pro Länge der Nadel im Gewebe (Dicke %1 mm): C, D in N/m, b in N·s/m²
</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>group             statistic freq_Hz </source>
        <translation>group             statistic freq_Hz </translation>
    </message>
    <message>
        <location line="+0"/>
        <source>  m_est_kg </source>
        <translation>  m_est_kg </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>       Cp        Bp        Cn        Bn        Dp        Dn
</source>
        <translation>       Cp        Bp        Cn        Bn        Dp        Dn
</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>no result</source>
        <translation>kein Erg.</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>%1: standard errors of D per length: Dp ±%2, Dn ±%3 (the spread of %4 and %5 break-aways)
</source>
        <translation>%1: Standardfehler von D pro Länge: Dp ±%2, Dn ±%3 (die Streuung von %4 und %5 Losbrech-Kräften)
</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>above %1 mm/s</source>
        <translation>über %1 mm/s</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>not seen</source>
        <translation>nicht gesehen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: the tissue was still arriving at the plate as the needle passed its top speed (+ motion: %2, - motion: %3); those samples are left out of the sliding line and the peak point
</source>
        <translation>%1: Das Gewebe kam noch an der Lochplatte an, als die Nadel ihre Höchstgeschwindigkeit durchlief (+-Bewegung: %2, −-Bewegung: %3); diese Messpunkte bleiben aus der Gleitgeraden und dem Spitzenpunkt heraus
</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>+ motion</source>
        <translation>+-Bewegung</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>- motion</source>
        <translation>−-Bewegung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: in %2 the slab gives against the plate by %3 N/m up to %4 N (read where the needle carries it in, %5 times); C and b are taken against the tissue&apos;s motion where it rests on that give
</source>
        <translation>%1: in %2 gibt die Gewebeplatte an der Lochplatte mit %3 N/m nach, bis %4 N (gelesen, wo die Nadel sie hineinträgt, %5-mal); C und b werden gegen die Bewegung des Gewebes genommen, wo es auf dieser Nachgiebigkeit ruht
</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: NOT A RESULT (not physical, or not determined by this run): %2
</source>
        <translation>%1: KEIN ERGEBNIS (nicht physikalisch oder von diesem Lauf nicht bestimmt): %2
</translation>
    </message>
    <message>
        <location line="-60"/>
        <location filename="../app/cmd_plan.cpp" line="-29"/>
        <source>run</source>
        <translation>run</translation>
    </message>
    <message>
        <location line="-227"/>
        <source>Usage: needlebench fit friction RUN.csv... --thickness-mm T [--mass-kg M | --estimate-mass] [--band-m-s B] [--labels FILE] [--tissue-trace FILE.csv] [--json]
</source>
        <translation>Aufruf: needlebench fit friction LAUF.csv... --thickness-mm T [--mass-kg M | --estimate-mass] [--band-m-s B] [--labels DATEI] [--tissue-trace DATEI.csv] [--json]
</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>--tissue-trace applies to a single run; give one run per call</source>
        <translation>--tissue-trace gilt für einen einzelnen Lauf; geben Sie einen Lauf pro Aufruf an</translation>
    </message>
    <message>
        <location line="+195"/>
        <source>%1Hz (%2 runs)</source>
        <translation>%1 Hz (%2 Läufe)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+3"/>
        <source>mean</source>
        <translation>mean</translation>
    </message>
    <message>
        <location line="-2"/>
        <location line="+3"/>
        <source>std</source>
        <translation>std</translation>
    </message>
    <message>
        <location line="-1"/>
        <location line="+1"/>
        <source>all (%1 runs)</source>
        <translation>alle (%1 Läufe)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>peak speeds</source>
        <translation>Spitzengeschw.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>line</source>
        <translation>Gerade</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: D from %2, rms %3 N
</source>
        <translation>%1: D aus %2, RMS %3 N
</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: zero-velocity band found in the data: ±%2 mm/s after turning points, ±%3 mm/s before them
</source>
        <translation>%1: Nullgeschwindigkeitsband aus den Daten: ±%2 mm/s nach Umkehrpunkten, ±%3 mm/s davor
</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: zero-velocity band ±%2 mm/s (given)
</source>
        <translation>%1: Nullgeschwindigkeitsband ±%2 mm/s (vorgegeben)
</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: C and b fitted against the needle&apos;s velocity relative to the tissue&apos;s (%2)
</source>
        <translation>%1: C und b gegen die Geschwindigkeit der Nadel relativ zu der des Gewebes angepasst (%2)
</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: standard errors per length: Cp ±%2, bp ±%3, Cn ±%4, bn ±%5
</source>
        <translation>%1: Standardfehler je Länge: Cp ±%2, bp ±%3, Cn ±%4, bn ±%5
</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 N/m</source>
        <translation>%1 N/m</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>no give seen</source>
        <translation>kein Nachgeben zu sehen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: the slab springs back off the plate as the needle slows (its stiffness against the plate: %2 in + motion, %3 in - motion); C and b are taken against the tissue&apos;s motion
</source>
        <translation>%1: Die Gewebeplatte federt von der Lochplatte zurück, während die Nadel langsamer wird (ihre Steifigkeit gegen die Lochplatte: %2 in +-Bewegung, %3 in −-Bewegung); C und b beziehen sich auf die Bewegung relativ zum Gewebe
</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1: C departs from the peak-speed line (Cp %2 %, Cn %3 %): the tissue moves while the needle slows, so this run&apos;s sliding line is tilted; prefer the peak-speed line
</source>
        <translation>%1: C weicht von der Geraden durch die Spitzengeschwindigkeiten ab (Cp %2 %, Cn %3 %): das Gewebe bewegt sich, während die Nadel abbremst, daher ist die Gleitgerade dieses Laufs gekippt; die Gerade durch die Spitzengeschwindigkeiten ist vorzuziehen
</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>peak-speed line: C and b through the top speeds of %1 runs (%2 to %3 mm/s), where the needle does not accelerate and the tissue rests against the plate; standard errors per length: Cp ±%4, bp ±%5, Cn ±%6, bn ±%7
</source>
        <translation>Gerade durch die Spitzengeschwindigkeiten: C und b aus den Höchstgeschwindigkeiten von %1 Läufen (%2 bis %3 mm/s), wo die Nadel nicht beschleunigt und das Gewebe an der Platte ruht; Standardfehler pro Länge: Cp ±%4, bp ±%5, Cn ±%6, bn ±%7
</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>no peak-speed line: it needs three runs or more whose tissue settled at the top and whose top speeds differ by a fifth or more (e.g. the same slab at 0.2, 0.5 and 0.8 Hz)
</source>
        <translation>keine Gerade durch die Spitzengeschwindigkeiten: Sie braucht drei Läufe oder mehr, deren Gewebe an der Spitze zur Ruhe kam und deren Spitzengeschwindigkeiten sich um ein Fünftel oder mehr unterscheiden (z. B. dieselbe Gewebeplatte bei 0,2, 0,5 und 0,8 Hz)
</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Usage: needlebench fit calibration FILE.csv [--json]
       needlebench fit stiffness RUN.csv... [--json]
       needlebench fit friction RUN.csv... --thickness-mm T [--mass-kg M | --estimate-mass]
                                [--band-m-s B] [--labels FILE] [--json]
&apos;needlebench fit WHAT --help&apos; describes each.
</source>
        <translation>Aufruf: needlebench fit calibration DATEI.csv [--json]
        needlebench fit stiffness LAUF.csv... [--json]
        needlebench fit friction LAUF.csv... --thickness-mm T [--mass-kg M | --estimate-mass]
                                 [--band-m-s B] [--labels DATEI] [--json]
&apos;needlebench fit WAS --help&apos; beschreibt jeden Fit.
</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>needlebench fit: say what to fit
</source>
        <translation>needlebench fit: bitte angeben, was gefittet werden soll
</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>needlebench fit: unknown fit &apos;%1&apos;
</source>
        <translation>needlebench fit: unbekannter Fit &apos;%1&apos;
</translation>
    </message>
    <message>
        <location filename="../app/cmd_labels.cpp" line="-83"/>
        <source>Labels of a run. Actions: suggest (phases or events from the data).</source>
        <translation>Labels eines Laufs. Aktionen: suggest (Phasen oder Ereignisse aus den Daten).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>suggest</source>
        <translation>suggest</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../app/cmd_sync.cpp" line="-78"/>
        <source>the run file</source>
        <translation>die Laufdatei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>labels file to write (default RUN.labels.csv)</source>
        <translation>zu schreibende Label-Datei (Standard LAUF.labels.csv)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>print the labels as JSON</source>
        <translation>die Labels als JSON ausgeben</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>video time at the recording&apos;s start (default: the run&apos;s stored sync, else found automatically)</source>
        <translation>Videozeit beim Start der Aufnahme (Standard: die gespeicherte Synchronisation der Messung, sonst automatisch ermittelt)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the video clock&apos;s rate error, e.g. 0.001 (default 0)</source>
        <translation>Gangfehler der Videouhr, z. B. 0,001 (Standard 0)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>write the tissue&apos;s velocity read off the video as CSV (time_s,tissue_velocity_mm_s)</source>
        <translation>die aus dem Video gelesene Geschwindigkeit des Gewebes als CSV schreiben (time_s,tissue_velocity_mm_s)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>needlebench labels: unknown action &apos;%1&apos; (suggest)

</source>
        <translation>needlebench labels: unbekannte Aktion &apos;%1&apos; (suggest)

</translation>
    </message>
    <message>
        <location line="+17"/>
        <location line="+6"/>
        <source>the labels file</source>
        <translation>die Label-Datei</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1: a folder, not a video</source>
        <translation>%1: ein Ordner, kein Video</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: no such video</source>
        <translation>%1: dieses Video gibt es nicht</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>needlebench labels: --video-offset-s wants seconds and --video-drift a rate error below 0.1
</source>
        <translation>needlebench labels: --video-offset-s erwartet Sekunden und --video-drift einen Gangfehler unter 0,1
</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: too few samples (%2) to suggest labels</source>
        <translation>%1: zu wenige Messwerte (%2), um Labels vorzuschlagen</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>needlebench labels: the run&apos;s video %1 is missing; looking beside the run
</source>
        <translation>needlebench labels: das Video des Laufs, %1, fehlt; es wird neben dem Lauf gesucht
</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>needlebench labels: no video for %1 (none linked, none beside it): --video-offset-s and --video-drift are not used
</source>
        <translation>needlebench labels: kein Video zu %1 (keines verknüpft, keines daneben): --video-offset-s und --video-drift werden nicht verwendet
</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>needlebench labels: %1: the surface&apos;s motion could not be read (%2); no relaxation suggested
</source>
        <translation>needlebench labels: %1: die Bewegung der Oberfläche ließ sich nicht lesen (%2); keine Relaxation vorgeschlagen
</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>needlebench labels: %1: the tissue&apos;s motion could not be read (%2); phases from force and position only
</source>
        <translation>needlebench labels: %1: Die Bewegung des Gewebes ließ sich nicht lesen (%2); Phasen nur aus Kraft und Position
</translation>
    </message>
    <message>
        <location line="-146"/>
        <source>the run&apos;s imaging video: friction phases also from the tissue&apos;s motion in it, the relaxation of insertion runs from the surface&apos;s spring-back (default: the video linked to the run, else RUN.mp4, RUN.avi… beside it)</source>
        <translation>das Bildgebungsvideo der Messung: Reibungsphasen auch aus der Gewebebewegung darin, die Relaxation von Einstichmessungen aus dem Zurückfedern der Oberfläche (Standard: das mit der Messung verknüpfte Video, sonst RUN.mp4, RUN.avi… daneben)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>replace an existing labels file (it may hold labels made by hand), and let --tissue-trace replace a file that is not a trace</source>
        <translation>eine vorhandene Label-Datei ersetzen (sie kann von Hand gesetzte Labels enthalten) und --tissue-trace eine Datei ersetzen lassen, die kein Verlauf ist</translation>
    </message>
    <message>
        <location line="+140"/>
        <source>needlebench labels: %1: no relaxation suggested: %2
</source>
        <translation>needlebench labels: %1: keine Relaxation vorgeschlagen: %2
</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>%1 labels suggested, written to %2
</source>
        <translation>%1 Labels vorgeschlagen, nach %2 geschrieben
</translation>
    </message>
    <message>
        <location filename="../app/cmd_simulate.cpp" line="-288"/>
        <source>stiffness|internal|friction|prostate</source>
        <translation>stiffness|internal|friction|prostate</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>liver1|liver2|liver3|liver5|liver7|prostate</source>
        <translation>liver1|liver2|liver3|liver5|liver7|prostate</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>beveled|diamond|blunt</source>
        <translation>beveled|diamond|blunt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>random seed (default 1)</source>
        <translation>Zufallsstartwert (Standard 1)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>insertion velocity (default 4, internal 2.5)</source>
        <translation>Einstichgeschwindigkeit (Standard 4, intern 2,5)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>sine amplitude, at most the stage&apos;s 10 mm travel (default 10)</source>
        <translation>Sinus-Amplitude, höchstens der Verfahrweg der Achse von 10 mm (Standard 10)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>tissue slab thickness on the friction platform (default 30)</source>
        <translation>Dicke der Gewebescheibe auf der Reibungsplattform (Standard 30)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bone this far below the surface (very stiff)</source>
        <translation>Knochen so weit unter der Oberfläche (sehr steif)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>run on the wall clock (default: as fast as possible)</source>
        <translation>nach der Wanduhr laufen (Standard: so schnell wie möglich)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>write the ground truth as JSON</source>
        <translation>die Referenzwerte als JSON schreiben</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>also render the imaging view (29.97 frames/s; .avi, .mkv or .mp4)</source>
        <translation>auch die Bildgebungsansicht rendern (29,97 Bilder/s; .avi, .mkv oder .mp4)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>friction platform: the tissue sticks while the relative velocity is within ±V (default 2.5)</source>
        <translation>Reibungsplattform: das Gewebe haftet, solange die Relativgeschwindigkeit innerhalb ±V liegt (Standard 2,5)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>friction platform: free travel of the slab before it meets a plate (default 1.5)</source>
        <translation>Reibungsplattform: freier Weg der Gewebeplatte, bevor sie an eine Platte stößt (Standard 1,5)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rms noise of the force sensor in newtons (default about 0.0012)</source>
        <translation>Effektivwert des Rauschens des Kraftsensors in Newton (Standard etwa 0,0012)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>replace existing output files (--out, --truth, --video)</source>
        <translation>vorhandene Ausgabedateien ersetzen (--out, --truth, --video)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>--%1: &apos;%2&apos; is not a number</source>
        <translation>--%1: &apos;%2&apos; ist keine Zahl</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>--protocol is required (%1)</source>
        <translation>--protocol ist erforderlich (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown protocol &apos;%1&apos; (%2)</source>
        <translation>unbekanntes Protokoll &apos;%1&apos; (%2)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>--truth and --out name the same file %1</source>
        <translation>--truth und --out nennen dieselbe Datei %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>--video names the same file as --out or --truth: %1</source>
        <translation>--video nennt dieselbe Datei wie --out oder --truth: %1</translation>
    </message>
    <message>
        <location line="+19"/>
        <location filename="../app/plan_runner.cpp" line="+109"/>
        <source>unknown tissue &apos;%1&apos; (%2)</source>
        <translation>unbekanntes Gewebe &apos;%1&apos; (%2)</translation>
    </message>
    <message>
        <location line="+4"/>
        <location filename="../app/plan_runner.cpp" line="+6"/>
        <source>unknown tip &apos;%1&apos; (beveled|diamond|blunt)</source>
        <translation>unbekannte Spitze &apos;%1&apos; (beveled|diamond|blunt)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>--seed: &apos;%1&apos; is not a non-negative integer</source>
        <translation>--seed: &apos;%1&apos; ist keine nichtnegative ganze Zahl</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>--rate-hz must be between 100 and 10000 (got %1)</source>
        <translation>--rate-hz muss zwischen 100 und 10000 liegen (erhalten: %1)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--velocity-mm-s must be in (0, %1]</source>
        <translation>--velocity-mm-s muss in (0, %1] liegen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--depth-mm must be in (0, %1]</source>
        <translation>--depth-mm muss in (0, %1] liegen</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>--amplitude-mm must be in (0, %1]</source>
        <translation>--amplitude-mm muss in (0, %1] liegen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>--frequency-hz must be in [0.01, 5]</source>
        <translation>--frequency-hz muss in [0.01, 5] liegen</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--thickness-mm must be in (0, %1]</source>
        <translation>--thickness-mm muss in (0, %1] liegen</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--cycles must be a whole number in [1, 1000]</source>
        <translation>--cycles muss eine ganze Zahl in [1, 1000] sein</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>--bone-depth-mm must be in (0, %1]</source>
        <translation>--bone-depth-mm muss in (0, %1] liegen</translation>
    </message>
    <message>
        <location line="+111"/>
        <source>the run did not end by itself: no truth or video is written for it</source>
        <translation>der Lauf endete nicht von selbst: für ihn werden keine Referenzwerte und kein Video geschrieben</translation>
    </message>
    <message>
        <location line="-269"/>
        <source>the video starts this long before the recording; negative: after it began (-600 to 600, default 0)</source>
        <translation>das Video beginnt so lange vor der Aufnahme; negativ: nach ihrem Beginn (-600 bis 600, Standard 0)</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>--video-offset-s wants seconds between -600 and 600</source>
        <translation>--video-offset-s erwartet Sekunden zwischen -600 und 600</translation>
    </message>
    <message>
        <location line="+67"/>
        <source>--max-force-n must be in [0.01, 100]</source>
        <translation>--max-force-n muss in [0.01, 100] liegen</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>--stick-band-mm-s must be in (0, 50]</source>
        <translation>--stick-band-mm-s muss in (0, 50] liegen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>--plate-gap-mm must be in [0, 20]</source>
        <translation>--plate-gap-mm muss in [0, 20] liegen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--force-noise-n must be in [0, 1]</source>
        <translation>--force-noise-n muss in [0, 1] liegen</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>--slow-after-puncture must be in (0, %1] mm/s</source>
        <translation>--slow-after-puncture muss in (0, %1] mm/s liegen</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>warning: the disk holding %1 will be full in about %2 s at the current rate (%3 kB free)</source>
        <translation>Warnung: der Datenträger mit %1 ist bei der jetzigen Rate in etwa %2 s voll (%3 kB frei)</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Run &apos;needlebench simulate --help&apos; for the options.</source>
        <translation>&apos;needlebench simulate --help&apos; zeigt die Optionen.</translation>
    </message>
    <message>
        <location filename="../app/cmd_plan.cpp" line="-480"/>
        <source>Run &apos;needlebench plan %1 --help&apos; for the options.</source>
        <translation>&apos;needlebench plan %1 --help&apos; zeigt die Optionen.</translation>
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
        <translation>Aufruf: needlebench plan templates [--json]
        needlebench plan new --template NAME --out PLAN.json [--order listed|random|blocked] [--seed N]
                             [--set SCHLÜSSEL=WERT]... [--levels FAKTOR=S1,S2,...]...
        needlebench plan show PLAN.json [--json]
        needlebench plan run PLAN.json --session ORDNER [--daq DAQ --stage STAGE] [--yes]
        needlebench plan skip PLAN.json --run N --reason TEXT
        needlebench plan redo PLAN.json --run N [--reason TEXT]
        needlebench plan report SITZUNGSORDNER [--by FAKTOR,...] [--estimate-mass] [--json] [--out-dir ORDNER]
</translation>
    </message>
    <message>
        <location line="+54"/>
        <location line="+152"/>
        <source>runs</source>
        <translation>Läufe</translation>
    </message>
    <message>
        <location line="-144"/>
        <source>the template (see &apos;plan templates&apos;)</source>
        <translation>die Vorlage (siehe &apos;plan templates&apos;)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the plan file to write</source>
        <translation>die zu schreibende Plandatei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>listed | random | blocked (by site; default listed)</source>
        <translation>listed | random | blocked (nach Stelle; Vorgabe listed)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>seed of the random order and of the simulated runs (default 1)</source>
        <translation>Startwert der zufälligen Reihenfolge und der simulierten Läufe (Vorgabe 1)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>change a default setting, e.g. cycles=3 (repeatable)</source>
        <translation>eine Vorgabe ändern, z. B. cycles=3 (wiederholbar)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set a factor&apos;s levels, e.g. site=1,2,3 (repeatable; a new name adds a factor)</source>
        <translation>die Stufen eines Faktors setzen, z. B. site=1,2,3 (wiederholbar; ein neuer Name fügt einen Faktor hinzu)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>replace an existing file (never a plan with recorded runs)</source>
        <translation>eine vorhandene Datei ersetzen (nie einen Plan mit aufgezeichneten Läufen)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--template NAME is required (see &apos;needlebench plan templates&apos;)</source>
        <translation>--template NAME ist erforderlich (siehe &apos;needlebench plan templates&apos;)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>unknown template &apos;%1&apos; (%2)</source>
        <translation>unbekannte Vorlage &apos;%1&apos; (%2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>--out PLAN.json is required</source>
        <translation>--out PLAN.json ist erforderlich</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>--order must be listed, random or blocked (got &apos;%1&apos;)</source>
        <translation>--order muss listed, random oder blocked sein (erhalten: &apos;%1&apos;)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>--seed wants an integer from 0 to 4294967295 (got &apos;%1&apos;)</source>
        <translation>--seed erwartet eine ganze Zahl von 0 bis 4294967295 (erhalten: &apos;%1&apos;)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>--set %1: expected KEY=VALUE with KEY one of %2</source>
        <translation>--set %1: SCHLÜSSEL=WERT erwartet, SCHLÜSSEL einer von %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--set %1: %2 is a factor of this template; give its levels with --levels %2=...</source>
        <translation>--set %1: %2 ist ein Faktor dieser Vorlage; seine Stufen mit --levels %2=... angeben</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--levels %1: expected FACTOR=L1,L2,...</source>
        <translation>--levels %1: FAKTOR=S1,S2,... erwartet</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>needlebench plan new: note: &apos;%1&apos; is neither a setting of the rig nor a factor of this template (%2); it is added as a new factor that the operator sets</source>
        <translation>needlebench plan new: Hinweis: &apos;%1&apos; ist weder eine Einstellung des Versuchsstands noch ein Faktor dieser Vorlage (%2); er wird als neuer Faktor hinzugefügt, den der Bediener einstellt</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 holds a plan with recorded runs; it is not overwritten</source>
        <translation>%1 enthält einen Plan mit aufgezeichneten Läufen; er wird nicht überschrieben</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: %2 runs of &apos;%3&apos;, order %4, seed %5</source>
        <translation>%1: %2 Läufe von &apos;%3&apos;, Reihenfolge %4, Startwert %5</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>the plan file</source>
        <translation>die Plandatei</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 min of motion left</source>
        <translation>noch %1 min Bewegung</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>the run&apos;s number</source>
        <translation>die Nummer des Laufs</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>why (required to skip)</source>
        <translation>warum (zum Überspringen erforderlich)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the plan file (the session&apos;s plan.json)</source>
        <translation>die Plandatei (plan.json der Sitzung)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--reason TEXT is required</source>
        <translation>--reason TEXT ist erforderlich</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>--run: no run &apos;%1&apos; in %2</source>
        <translation>--run: kein Lauf &apos;%1&apos; in %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+161"/>
        <source>run %1: %2</source>
        <translation>Lauf %1: %2</translation>
    </message>
    <message>
        <location line="-150"/>
        <source>the session folder (created when missing; holds plan.json and the runs)</source>
        <translation>der Sitzungsordner (wird angelegt, wenn er fehlt; enthält plan.json und die Läufe)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>sim | u6 | u6:SERIAL (default sim)</source>
        <translation>sim | u6 | u6:SERIENNUMMER (Vorgabe sim)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sim | zaber:PORT (default sim)</source>
        <translation>sim | zaber:PORT (Vorgabe sim)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>on real devices, do not wait for Enter after an operator instruction</source>
        <translation>an echten Geräten nach einer Anweisung an den Bediener nicht auf die Eingabetaste warten</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the plan (from &apos;plan new&apos;, or the session&apos;s plan.json)</source>
        <translation>der Plan (aus &apos;plan new&apos; oder plan.json der Sitzung)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--session DIR is required</source>
        <translation>--session ORDNER ist erforderlich</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>%1 holds a different plan; to resume it run &apos;needlebench plan run %1 --session %2&apos;, or use another session folder</source>
        <translation>%1 enthält einen anderen Plan; zum Fortsetzen &apos;needlebench plan run %1 --session %2&apos; ausführen oder einen anderen Sitzungsordner wählen</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 is open in another NeedleBench (%2); close it there first</source>
        <translation>%1 ist in einem anderen NeedleBench offen (%2); dort zuerst schließen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>recovered %1</source>
        <translation>wiederhergestellt: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>run %1 had ended before the interruption: %2</source>
        <translation>Lauf %1 war vor der Unterbrechung beendet: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>run %1 was interrupted; it runs again</source>
        <translation>Lauf %1 wurde unterbrochen; er läuft erneut</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>the plan stops before run %1 (interrupted); run the same command again to resume</source>
        <translation>der Plan hält vor Lauf %1 an (unterbrochen); denselben Befehl erneut ausführen, um fortzufahren</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>operator: %1</source>
        <translation>Bediener: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>press Enter when done</source>
        <translation>Eingabetaste drücken, wenn erledigt</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>run %1 of %2: %3</source>
        <translation>Lauf %1 von %2: %3</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>interrupted</source>
        <translation>unterbrochen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the plan stops at run %1 (interrupted); run the same command again to resume</source>
        <translation>der Plan hält bei Lauf %1 an (unterbrochen); denselben Befehl erneut ausführen, um fortzufahren</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>done</source>
        <translation>fertig</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>done (%1)</source>
        <translation>fertig (%1)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>failed</source>
        <translation>fehlgeschlagen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the plan stops at run %1; fix the cause and run the same command again to resume</source>
        <translation>der Plan hält bei Lauf %1 an; die Ursache beheben und denselben Befehl erneut ausführen, um fortzusetzen</translation>
    </message>
    <message>
        <location line="+20"/>
        <location filename="../app/plan_runner.cpp" line="-27"/>
        <location filename="../app/simulated_run.cpp" line="+175"/>
        <source>cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Fitted quantities per run with their factor levels</source>
        <translation>Angepasste Größen je Lauf mit ihren Faktorstufen</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>factors to group by, comma separated (default: the plan&apos;s factors)</source>
        <translation>Faktoren zum Gruppieren, durch Kommas getrennt (Vorgabe: die Faktoren des Plans)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>fit friction with the mass estimated (eq. 19, as Table 5)</source>
        <translation>Reibung mit geschätzter Masse anpassen (Gl. 19, wie Tabelle 5)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>also write the tables here as CSV and LaTeX (by_factor, friction_by_frequency, runs_by_factor)</source>
        <translation>die Tabellen zusätzlich als CSV und LaTeX hierhin schreiben (by_factor, friction_by_frequency, runs_by_factor)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>include runs the plan does not count (interrupted, discarded)</source>
        <translation>auch Läufe einbeziehen, die der Plan nicht zählt (unterbrochen, verworfen)</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>--by FACTOR,... is required when the folder has no plan.json</source>
        <translation>--by FAKTOR,... ist erforderlich, wenn der Ordner keine plan.json enthält</translation>
    </message>
    <message numerus="yes">
        <location line="+23"/>
        <source>%n run(s) the plan does not count (interrupted, failed or discarded) left out: %1; --all-runs includes them</source>
        <translation>
            <numerusform>%n Lauf, den der Plan nicht zählt (abgebrochen, fehlgeschlagen oder verworfen), ausgelassen: %1; --all-runs nimmt ihn auf</numerusform>
            <numerusform>%n Läufe, die der Plan nicht zählt (abgebrochen, fehlgeschlagen oder verworfen), ausgelassen: %1; --all-runs nimmt sie auf</numerusform>
        </translation>
    </message>
    <message>
        <location line="+9"/>
        <source>--by %1: no run in %2 records a level of it (factors recorded: %3)</source>
        <translation>--by %1: kein Lauf in %2 verzeichnet eine Stufe davon (verzeichnete Faktoren: %3)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>none; settings such as tissue or tip work too</source>
        <translation>keine; Einstellungen wie tissue oder tip gehen auch</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>cannot create %1</source>
        <translation>%1 kann nicht angelegt werden</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>no run in %1 could be fitted</source>
        <translation>kein Lauf in %1 ließ sich anpassen</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>needlebench plan: unknown subcommand &apos;%1&apos;</source>
        <translation>needlebench plan: unbekannter Unterbefehl &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../app/cmd_sync.cpp" line="-1"/>
        <source>Find the video&apos;s offset to the force record (video time = recording time + offset).</source>
        <translation>Den Versatz des Videos zur Kraftaufzeichnung finden (Videozeit = Aufzeichnungszeit + Versatz).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the video of the run</source>
        <translation>das Video des Laufs</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>region of the picture that moves with the needle, in pixels</source>
        <translation>Bildbereich, der sich mit der Nadel bewegt, in Pixeln</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>largest offset to consider, seconds (default 20)</source>
        <translation>größter zu prüfender Versatz in Sekunden (Standard 20)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the needle&apos;s line in the picture, in pixels (default: found in the picture)</source>
        <translation>die Linie der Nadel im Bild, in Pixeln (Standard: im Bild gefunden)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the video is as its camera or console coded it, never converted: its coder&apos;s lag is then known more closely</source>
        <translation>das Video liegt so vor, wie Kamera oder Konsole es kodierten, nie umgewandelt: Die Verspätung seines Kodierers ist dann genauer bekannt</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>also write the needle&apos;s tracked displacement per frame (time_s,displacement_px) to FILE</source>
        <translation>zusätzlich die verfolgte Verschiebung der Nadel je Bild (time_s,displacement_px) in DATEI schreiben</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>let --trace replace a file that is not a trace (an earlier trace is replaced without it)</source>
        <translation>--trace eine Datei ersetzen lassen, die kein Verlauf ist (ein früherer Verlauf wird auch ohne dies ersetzt)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>needlebench sync: --roi wants x,y,w,h in whole pixels, w and h &gt; 0

</source>
        <translation>needlebench sync: --roi erwartet x,y,w,h in ganzen Pixeln, w und h &gt; 0

</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>needlebench sync: --needle wants x1,y1,x2,y2 in pixels, two distinct points

</source>
        <translation>needlebench sync: --needle erwartet x1,y1,x2,y2 in Pixeln, zwei verschiedene Punkte

</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>needlebench sync: --max-offset wants a positive number of seconds
</source>
        <translation>needlebench sync: --max-offset erwartet eine positive Anzahl Sekunden
</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>needlebench sync: %1: the picture is %2x%3 px, too small to show a needle (%4 px a side at least)
</source>
        <translation>needlebench sync: %1: das Bild hat %2x%3 px, zu klein, um eine Nadel zu zeigen (mindestens %4 px je Seite)
</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>needlebench sync: --roi %1,%2,%3,%4 lies outside the %5x%6 picture
</source>
        <translation>needlebench sync: --roi %1,%2,%3,%4 liegt außerhalb des Bildes von %5x%6
</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>needlebench sync: --needle %1,%2,%3,%4 lies outside the %5x%6 picture
</source>
        <translation>needlebench sync: --needle %1,%2,%3,%4 liegt außerhalb des Bildes von %5x%6
</translation>
    </message>
    <message numerus="yes">
        <location line="+14"/>
        <source>warning: %1: %n frame(s) in damaged stretches of the file, or after one up to the next keyframe, were left out</source>
        <translation>
            <numerusform>Warnung: %1: %n Bild in beschädigten Stellen der Datei oder dahinter bis zum nächsten Schlüsselbild wurde ausgelassen</numerusform>
            <numerusform>Warnung: %1: %n Bilder in beschädigten Stellen der Datei oder dahinter bis zum nächsten Schlüsselbild wurden ausgelassen</numerusform>
        </translation>
    </message>
    <message>
        <location line="+59"/>
        <source>offset:      %1 s (video time minus recording time)
</source>
        <translation>Versatz:     %1 s (Videozeit minus Aufzeichnungszeit)
</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>offset:      none (nothing in the picture moved with the recording)
</source>
        <translation>Versatz:     keiner (nichts im Bild bewegte sich mit der Aufzeichnung)
</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>confidence:  %1
</source>
        <translation>Konfidenz:   %1
</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>correlation: %1
</source>
        <translation>Korrelation: %1
</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>reversed:    the needle in the picture moves against the recorded position (a mirrored picture, or the position&apos;s sign)
</source>
        <translation>umgekehrt:   die Nadel im Bild bewegt sich gegen die aufgezeichnete Position (ein gespiegeltes Bild oder das Vorzeichen der Position)
</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>onsets say:  %1 s
</source>
        <translation>Bewegungsanfänge: %1 s
</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>drift:       %1 %
</source>
        <translation>Drift:       %1 %
</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>uncertainty: %1 frames
</source>
        <translation>Unsicherheit: %1 Bilder
</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>uncertainty: unknown (what moved in the picture does not time the offset)
</source>
        <translation>Unsicherheit: unbekannt (was sich im Bild bewegte, bestimmt den Versatz nicht)
</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>uncertainty: unknown (nothing in the picture moved with the recording)
</source>
        <translation>Unsicherheit: unbekannt (nichts im Bild bewegte sich mit der Aufzeichnung)
</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>coded late:  %1 frames (taken off the offset), known to ±%2 frames
</source>
        <translation>kodiert spät: %1 Bilder (vom Versatz abgezogen), auf ±%2 Bilder genau
</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>needle:      %1,%2 to %3,%4 (%5)
</source>
        <translation>Nadel:       %1,%2 bis %3,%4 (%5)
</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>found in the picture</source>
        <translation>im Bild gefunden</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>given</source>
        <translation>vorgegeben</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>method:      %1
</source>
        <translation>Methode:     %1
</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>tracked:     %1 to %2 s of %3 s (as far as the offsets tried reach)
</source>
        <translation>verfolgt:    %1 bis %2 s von %3 s (so weit die versuchten Versätze reichen)
</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>LOW CONFIDENCE (below %1): check the offset by marking an event in both before using it
</source>
        <translation>GERINGE KONFIDENZ (unter %1): den Versatz vor der Verwendung prüfen, indem ein Ereignis in beiden markiert wird
</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the video&apos;s coder shows this slow needle late by an amount known only to ±%1 frames: a region or a needle line will not make it surer, an event marked in both will
</source>
        <translation>der Kodierer des Videos zeigt diese langsame Nadel um einen nur auf ±%1 Bilder bekannten Betrag verspätet: ein Bereich oder eine Nadellinie machen das nicht sicherer, ein in beiden markiertes Ereignis schon
</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>if nobody converted this video (it is as its camera or console coded it), --coded-once narrows that
</source>
        <translation>hat niemand dieses Video umgewandelt (liegt es so vor, wie Kamera oder Konsole es kodierten), engt --coded-once das ein
</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>offsets were tried within ±%1 s (--max-offset): if the video started further from the recording than that, try a larger --max-offset
</source>
        <translation>Versätze wurden innerhalb ±%1 s versucht (--max-offset): begann das Video weiter von der Aufzeichnung entfernt, ein größeres --max-offset versuchen
</translation>
    </message>
    <message numerus="yes">
        <location line="+12"/>
        <source>the video %1 has only %n frame(s)</source>
        <translation>
            <numerusform>das Video %1 hat nur %n Bild</numerusform>
            <numerusform>das Video %1 hat nur %n Bilder</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>the run %1 has only %n sample(s)</source>
        <translation>
            <numerusform>der Lauf %1 hat nur %n Messwert</numerusform>
            <numerusform>der Lauf %1 hat nur %n Messwerte</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>cannot synchronise %1 with %2: %3</source>
        <translation>%1 kann nicht mit %2 synchronisiert werden: %3</translation>
    </message>
    <message>
        <location filename="../app/cmd_video.cpp" line="-38"/>
        <source>Index a video file frame by frame and describe it.</source>
        <translation>Eine Videodatei Bild für Bild indizieren und beschreiben.</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+34"/>
        <source>the video file</source>
        <translation>die Videodatei</translation>
    </message>
    <message>
        <location filename="../app/cmd_sync.cpp" line="-152"/>
        <location filename="../app/cmd_video.cpp" line="-24"/>
        <source>warning: %1: %2</source>
        <translation>Warnung: %1: %2</translation>
    </message>
    <message>
        <location filename="../app/cmd_video.cpp" line="+4"/>
        <source>file:        %1
</source>
        <translation>Datei:       %1
</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>codec:       %1
</source>
        <translation>Codec:       %1
</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>size:        %1x%2
</source>
        <translation>Größe:       %1x%2
</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>frames:      %1
</source>
        <translation>Bilder:      %1
</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rate:        %1 frames/s nominal%2
</source>
        <translation>Rate:        %1 Bilder/s nominal%2
</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>, variable</source>
        <translation>, variabel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>duration:    %1 s
</source>
        <translation>Dauer:       %1 s
</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>duplicates:  %1
</source>
        <translation>Duplikate:   %1
</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Write frame N (N-th in presentation order, from 0) of a video as an image.</source>
        <translation>Bild N eines Videos (N-tes in Anzeigereihenfolge, ab 0) als Bilddatei schreiben.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>frame number, from 0</source>
        <translation>Bildnummer, ab 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>image to write (.png)</source>
        <translation>zu schreibendes Bild (.png)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>needlebench frame: --index N (a whole number &gt;= 0) and --out IMAGE are required

</source>
        <translation>needlebench frame: --index N (eine ganze Zahl &gt;= 0) und --out BILD sind erforderlich

</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>needlebench frame: --out %1: not an image type that can be written (use .png, .tif or .jpg)
</source>
        <translation>needlebench frame: --out %1: kein Bildtyp, der geschrieben werden kann (.png, .tif oder .jpg verwenden)
</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>needlebench frame: %1: frame %2 does not exist (the video has %3 frames)
</source>
        <translation>needlebench frame: %1: Bild %2 gibt es nicht (das Video hat %3 Bilder)
</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>needlebench frame: %1: %2
</source>
        <translation>needlebench frame: %1: %2
</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>needlebench frame: %1: cannot write the image
</source>
        <translation>needlebench frame: %1: das Bild kann nicht geschrieben werden
</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>frame %1 at %2 s written to %3
</source>
        <translation>Bild %1 bei %2 s nach %3 geschrieben
</translation>
    </message>
    <message>
        <location filename="../app/cli_support.cpp" line="+22"/>
        <source>show this help</source>
        <translation>diese Hilfe anzeigen</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>missing arguments</source>
        <translation>fehlende Argumente</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>too many arguments</source>
        <translation>zu viele Argumente</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>%1 %2 is a file this command reads; writing it would destroy it. Name another file.</source>
        <translation>%1 %2 ist eine Datei, die dieser Befehl liest; sie zu schreiben würde sie zerstören. Geben Sie eine andere Datei an.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 %2 already exists; it is kept. Name another file, or add --overwrite to replace it.</source>
        <translation>%1 %2 existiert bereits; sie bleibt erhalten. Geben Sie eine andere Datei an oder fügen Sie --overwrite hinzu, um sie zu ersetzen.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 %2 already exists and is not a trace this command wrote; it is kept. Name another file, or add --overwrite to replace it.</source>
        <translation>%1 %2 existiert bereits und ist kein Verlauf, den dieser Befehl geschrieben hat; sie bleibt erhalten. Geben Sie eine andere Datei an oder fügen Sie --overwrite hinzu, um sie zu ersetzen.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 %2 is a folder; name a file</source>
        <translation>%1 %2 ist ein Ordner; geben Sie eine Datei an</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 %2: the folder %3 does not exist</source>
        <translation>%1 %2: der Ordner %3 existiert nicht</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 %2: no file can be written in %3 (%4)</source>
        <translation>%1 %2: in %3 kann keine Datei geschrieben werden (%4)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 %2: %3</source>
        <translation>%1 %2: %3</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>warning: %1 is a friction run (a sine on the platform, by its header); contact, punctures and stiffness are read for insertion runs and mean little here (&apos;needlebench fit friction&apos; fits it)</source>
        <translation>Warnung: %1 ist ein Reibungslauf (laut Kopfzeilen ein Sinus auf der Plattform); Kontakt, Durchstiche und Steifigkeit werden für Einstichläufe bestimmt und sagen hier wenig aus (&apos;needlebench fit friction&apos; passt ihn an)</translation>
    </message>
    <message>
        <location filename="../app/commands.cpp" line="+28"/>
        <source>print the version</source>
        <translation>die Version ausgeben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fit calibration, stiffness or friction models</source>
        <translation>Kalibrier-, Steifigkeits- oder Reibungsmodelle fitten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>find contact, punctures and relaxation in a run</source>
        <translation>Kontakt, Durchstiche und Relaxation in einem Lauf finden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>list connected DAQs and serial ports</source>
        <translation>angeschlossene Messkarten und serielle Schnittstellen auflisten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>record one run on real (or simulated) devices</source>
        <translation>einen Lauf auf echten (oder simulierten) Geräten aufzeichnen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>export a session as CSV, HDF5 or ELAN files</source>
        <translation>eine Sitzung als CSV-, HDF5- oder ELAN-Dateien exportieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>simulate, label, fit and export a short session</source>
        <translation>eine kurze Sitzung simulieren, markieren, fitten und exportieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>record one run on the simulated rig</source>
        <translation>einen Lauf auf dem simulierten Versuchsstand aufzeichnen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>index a video: frames, rate, duplicates</source>
        <translation>ein Video indizieren: Bilder, Rate, Duplikate</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>write one exact video frame as an image</source>
        <translation>ein exaktes Videobild als Bilddatei schreiben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>find the video&apos;s offset to a run (motion vs needle speed)</source>
        <translation>den Versatz eines Videos zu einem Lauf finden (Bewegung gegen Nadelgeschwindigkeit)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>suggest phase and event labels for a run</source>
        <translation>Phasen- und Ereignis-Labels für einen Lauf vorschlagen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>experiment plans: templates, new, run (resumes), report by factor</source>
        <translation>Versuchspläne: Vorlagen, neu, ausführen (setzt fort), Auswertung nach Faktoren</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Usage: needlebench                 open the workbench (GUI, simulated rig)
       needlebench COMMAND [options]  run headless

Commands:
</source>
        <translation>Aufruf: needlebench                 öffnet die Werkbank (GUI, simulierter Versuchsstand)
        needlebench BEFEHL [Optionen]  läuft ohne Oberfläche

Befehle:
</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>
&apos;needlebench COMMAND --help&apos; describes a command.
</source>
        <translation>
&apos;needlebench BEFEHL --help&apos; beschreibt einen Befehl.
</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>
Exit status: 0 done; 1 failed (the message says why, naming the file or device); 2 the command was given wrongly; 128+N ended by signal N (130 Ctrl+C, 143 SIGTERM), what was recorded closed.
</source>
        <translation>
Exit-Status: 0 erledigt; 1 fehlgeschlagen (die Meldung sagt warum und nennt die Datei oder das Gerät); 2 der Befehl war falsch angegeben; 128+N durch Signal N beendet (130 Strg+C, 143 SIGTERM), das Aufgezeichnete geschlossen.
</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>needlebench: unknown command &apos;%1&apos;

</source>
        <translation>needlebench: unbekannter Befehl &apos;%1&apos;

</translation>
    </message>
    <message>
        <location filename="../app/plan_runner.cpp" line="-20"/>
        <source>cannot read %1: %2</source>
        <translation>%1 kann nicht gelesen werden: %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: no column header</source>
        <translation>%1: keine Spaltenüberschrift</translation>
    </message>
    <message>
        <location line="+130"/>
        <source>the run did not start (exit code %1)</source>
        <translation>der Lauf hat nicht begonnen (Rückgabewert %1)</translation>
    </message>
    <message>
        <location filename="../app/guarded_main.cpp" line="+19"/>
        <source>out of memory</source>
        <translation>kein Speicher mehr</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>unknown exception</source>
        <translation>unbekannte Ausnahme</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>internal error: %1</source>
        <translation>interner Fehler: %1</translation>
    </message>
    <message>
        <location filename="../app/simulated_run.cpp" line="-34"/>
        <source>interrupted while the video was rendered: %1 and the truth are not written; the run file %2 is whole</source>
        <translation>beim Rendern des Videos unterbrochen: %1 und die Referenzwerte werden nicht geschrieben; die Laufdatei %2 ist vollständig</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: only %2 of %3 frames could be written (disk full?); removed</source>
        <translation>%1: nur %2 von %3 Bildern konnten geschrieben werden (Datenträger voll?); entfernt</translation>
    </message>
    <message>
        <location filename="../app/main.cpp" line="+122"/>
        <source>needlebench %1: &apos;%2&apos; is not UTF-8, so it cannot be opened by name here: rename it (for example with convmv -f latin1 -t utf8 --notest)</source>
        <translation>needlebench %1: „%2“ ist kein UTF-8 und lässt sich hier nicht unter diesem Namen öffnen: bitte umbenennen (zum Beispiel mit convmv -f latin1 -t utf8 --notest)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>needlebench %1: the output could not be written (%2)</source>
        <translation>needlebench %1: die Ausgabe konnte nicht geschrieben werden (%2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>write error</source>
        <translation>Schreibfehler</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Run a command without the window, such as &apos;needlebench demo&apos;; &apos;needlebench --help&apos; lists them.</source>
        <translation>Führen Sie einen Befehl ohne Fenster aus, etwa &apos;needlebench demo&apos;; &apos;needlebench --help&apos; listet sie auf.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>needlebench: no display to open the workbench on (neither DISPLAY nor WAYLAND_DISPLAY is set). Log in to a desktop or use ssh -X.</source>
        <translation>needlebench: kein Bildschirm, auf dem die Werkbank geöffnet werden kann (weder DISPLAY noch WAYLAND_DISPLAY ist gesetzt). Melden Sie sich an einem Desktop an oder verwenden Sie ssh -X.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>needlebench: the workbench cannot open on the display &apos;%1&apos; (see above): is the desktop still running, or the SSH session still forwarding X?</source>
        <translation>needlebench: Die Werkbank kann auf dem Bildschirm &apos;%1&apos; nicht geöffnet werden (siehe oben): Läuft der Desktop noch, oder leitet die SSH-Sitzung X noch weiter?</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>needlebench: unknown option &apos;%1&apos;; &apos;needlebench --help&apos; lists the commands and their options</source>
        <translation>needlebench: unbekannte Option &apos;%1&apos;; &apos;needlebench --help&apos; listet die Befehle und ihre Optionen auf</translation>
    </message>
</context>
<context>
    <name>nb::TrCore</name>
    <message>
        <location filename="../core/export/dataset.cpp" line="+19"/>
        <source>time since the start of the recording</source>
        <translation>Zeit seit Beginn der Aufzeichnung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>needle tip depth, grows as the needle goes deeper</source>
        <translation>Tiefe der Nadelspitze, wächst mit dem Eindringen</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>needle velocity, recorded</source>
        <translation>Nadelgeschwindigkeit, aufgezeichnet</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>needle velocity, central differences of position</source>
        <translation>Nadelgeschwindigkeit, zentrale Differenzen der Position</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>needle acceleration, recorded</source>
        <translation>Nadelbeschleunigung, aufgezeichnet</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>needle acceleration, central differences of velocity</source>
        <translation>Nadelbeschleunigung, zentrale Differenzen der Geschwindigkeit</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>axial force, positive when the tissue pushes back</source>
        <translation>Axialkraft, positiv wenn das Gewebe zurückdrückt</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the sensor&apos;s sample counter (a gap is a lost sample)</source>
        <translation>Messwertzähler des Sensors (eine Lücke ist ein verlorener Messwert)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>friction phase recorded with the run (the simulated rig&apos;s own)</source>
        <translation>mit dem Lauf aufgezeichnete Reibungsphase (die des simulierten Prüfstands)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>event recorded with the run at the sample</source>
        <translation>mit dem Lauf beim Messpunkt aufgezeichnetes Ereignis</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>text recorded with the run</source>
        <translation>mit dem Lauf aufgezeichneter Text</translation>
    </message>
    <message>
        <location line="+151"/>
        <source>%1: frames numbered from the run&apos;s frame rate, the video could not be indexed (%2)</source>
        <translation>%1: Bilder nach der Bildrate der Messung nummeriert, das Video ließ sich nicht indizieren (%2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no frames</source>
        <translation>keine Bilder</translation>
    </message>
    <message>
        <location filename="../core/export/dataset_loader.cpp" line="+43"/>
        <source>%1: label &apos;%2&apos; (%3 s to %4 s) reaches beyond the run (%5 s to %6 s); its part from %7 s to %8 s is used</source>
        <translation>%1: Label &apos;%2&apos; (%3 s bis %4 s) reicht über den Lauf hinaus (%5 s bis %6 s); sein Teil von %7 s bis %8 s wird verwendet</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>not a folder</source>
        <translation>kein Ordner</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>no such folder</source>
        <translation>Ordner existiert nicht</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1: skipped, %2</source>
        <translation>%1: übersprungen, %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: left out, the run is still recording or was cut off before it was closed (export it after it ends; a cut-off run is recovered when its session is opened in the window)</source>
        <translation>%1: ausgelassen, der Lauf zeichnet noch auf oder wurde abgebrochen, bevor er geschlossen war (nach seinem Ende exportieren; ein abgebrochener Lauf wird wiederhergestellt, wenn seine Sitzung im Fenster geöffnet wird)</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>%1: skipped, not a run file (%2)</source>
        <translation>%1: übersprungen, keine Laufdatei (%2)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1: labels ignored (%2)</source>
        <translation>%1: Labels ignoriert (%2)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1: its video %2 is missing; the export links none</source>
        <translation>%1: sein Video %2 fehlt; der Export verknüpft keines</translation>
    </message>
    <message>
        <location line="-127"/>
        <source>%1: label &apos;%2&apos; (%3 s to %4 s) lies outside the run (%5 s to %6 s); ignored</source>
        <translation>%1: Label &apos;%2&apos; (%3 s bis %4 s) liegt außerhalb des Laufs (%5 s bis %6 s); ignoriert</translation>
    </message>
    <message>
        <location filename="../core/export/run_csv_export.cpp" line="+78"/>
        <source>label of track &apos;%1&apos; active at the sample</source>
        <translation>zum Messwert aktives Label der Spur &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../core/export/csv_text.cpp" line="+37"/>
        <source>cannot write: no space left on the disk (%1 kB free)</source>
        <translation>kann nicht schreiben: kein Platz mehr auf dem Datenträger (%1 kB frei)</translation>
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
        <translation>kann nicht schreiben: %1</translation>
    </message>
    <message>
        <location filename="../core/export/session_analysis.cpp" line="+74"/>
        <source>%1: no stiffness fit (%2)</source>
        <translation>%1: kein Steifigkeitsfit (%2)</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1: no pooled stiffness fit (%2)</source>
        <translation>%1: kein gepoolter Steifigkeitsfit (%2)</translation>
    </message>
    <message>
        <location line="+39"/>
        <location line="+19"/>
        <source>%1: no friction fit (%2)</source>
        <translation>%1: kein Reibungsfit (%2)</translation>
    </message>
    <message>
        <location line="+64"/>
        <source>%1: no validation (%2)</source>
        <translation>%1: keine Validierung (%2)</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>Pre-puncture stiffness fits per run, f = a1 x + a2 x^2</source>
        <translation>Steifigkeitsfits vor dem Durchstich je Lauf, f = a1 x + a2 x^2</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+50"/>
        <location line="+75"/>
        <source>run</source>
        <translation>Lauf</translation>
    </message>
    <message>
        <location filename="../core/data_names.cpp" line="+53"/>
        <location filename="../core/export/session_analysis.cpp" line="-124"/>
        <location line="+26"/>
        <source>tissue</source>
        <translation>Gewebe</translation>
    </message>
    <message>
        <location filename="../core/export/session_analysis.cpp" line="-23"/>
        <location line="+49"/>
        <source>rms</source>
        <translation>RMS</translation>
    </message>
    <message>
        <location line="-47"/>
        <source>puncture depth</source>
        <translation>Durchstichtiefe</translation>
    </message>
    <message>
        <location line="-168"/>
        <location line="+169"/>
        <source>puncture force</source>
        <translation>Durchstichkraft</translation>
    </message>
    <message>
        <location line="-224"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>model force at %1 mm</source>
        <translation>Modellkraft bei %1 mm</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>no tissue contact</source>
        <translation>kein Gewebekontakt</translation>
    </message>
    <message>
        <location line="+145"/>
        <source>outlier</source>
        <translation>Ausreißer</translation>
    </message>
    <message>
        <location filename="../core/data_names.cpp" line="+47"/>
        <source>not fitted</source>
        <translation>nicht gefittet</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <location filename="../core/export/session_analysis.cpp" line="+17"/>
        <source>Pooled pre-puncture fits per tissue (Table 2 layout)</source>
        <translation>Gepoolte Fits vor dem Durchstich je Gewebe (Aufbau von Tabelle 2)</translation>
    </message>
    <message>
        <location filename="../core/data_names.cpp" line="-47"/>
        <location filename="../core/export/session_analysis.cpp" line="+3"/>
        <source>tip</source>
        <translation>Spitze</translation>
    </message>
    <message>
        <location filename="../core/export/session_analysis.cpp" line="+1"/>
        <source>fit</source>
        <translation>Fit</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>mean puncture depth</source>
        <translation>mittlere Durchstichtiefe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mean puncture force</source>
        <translation>mittlere Durchstichkraft</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+56"/>
        <source>runs</source>
        <translation>Läufe</translation>
    </message>
    <message>
        <location filename="../core/data_names.cpp" line="+41"/>
        <source>pooled</source>
        <translation>gepoolt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>mean of runs</source>
        <translation>Mittel der Läufe</translation>
    </message>
    <message>
        <location filename="../core/export/session_analysis.cpp" line="-42"/>
        <source>Karnopp friction per unit length of needle in tissue, per run</source>
        <translation>Karnopp-Reibung pro Länge der Nadel im Gewebe, je Lauf</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+39"/>
        <source>f</source>
        <translation>f</translation>
    </message>
    <message>
        <location line="-35"/>
        <source>D from</source>
        <translation>D aus</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not determined</source>
        <translation>nicht bestimmt</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Karnopp friction per unit length, mean and standard deviation per frequency and overall (Tables 4/5 layout)</source>
        <translation>Karnopp-Reibung pro Länge, Mittelwert und Standardabweichung je Frequenz und gesamt (Aufbau der Tabellen 4/5)</translation>
    </message>
    <message>
        <location filename="../core/export/factor_analysis.cpp" line="+246"/>
        <location filename="../core/export/session_analysis.cpp" line="+2"/>
        <source>group</source>
        <translation>Gruppe</translation>
    </message>
    <message>
        <location line="+0"/>
        <location filename="../core/export/session_analysis.cpp" line="+0"/>
        <source>statistic</source>
        <translation>Statistik</translation>
    </message>
    <message>
        <location filename="../core/data_names.cpp" line="+8"/>
        <location filename="../core/export/factor_analysis.cpp" line="-29"/>
        <source>std</source>
        <translation>std</translation>
    </message>
    <message>
        <location filename="../core/export/factor_analysis.cpp" line="-172"/>
        <source>%1: left out of the table: %2</source>
        <translation>%1: aus der Tabelle gelassen: %2</translation>
    </message>
    <message>
        <location line="+110"/>
        <source>%1: no friction fit with the mass estimated (%2)</source>
        <translation>%1: keine Reibungsanpassung mit geschätzter Masse (%2)</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>Fitted quantities by %1: mean, standard deviation and number of runs</source>
        <translation>Angepasste Größen nach %1: Mittelwert, Standardabweichung und Anzahl der Läufe</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>quantity</source>
        <translation>Größe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <location filename="../core/data_names.cpp" line="-2"/>
        <location filename="../core/export/factor_analysis.cpp" line="+1"/>
        <source>mean</source>
        <translation>Mittelwert</translation>
    </message>
    <message>
        <location filename="../core/export/factor_analysis.cpp" line="+28"/>
        <source>Karnopp friction per unit length, mean and standard deviation per frequency and overall (Table 5 layout)</source>
        <translation>Karnopp-Reibung je Längeneinheit, Mittelwert und Standardabweichung je Frequenz und gesamt (Aufbau von Tabelle 5)</translation>
    </message>
    <message>
        <location filename="../core/data_names.cpp" line="+10"/>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <location line="-6"/>
        <source>overall</source>
        <translation>gesamt</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>peak speeds</source>
        <translation>Spitzengeschwindigkeiten</translation>
    </message>
    <message>
        <location line="-18"/>
        <source>peak speeds, %1</source>
        <translation>Spitzengeschwindigkeiten, %1</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>line</source>
        <translation>Gerade</translation>
    </message>
    <message>
        <location filename="../core/export/session_analysis.cpp" line="+34"/>
        <source>Summed model against the recorded insertions (Fig. 38)</source>
        <translation>Summiertes Modell gegen die aufgezeichneten Einstiche (Abb. 38)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>rms error</source>
        <translation>RMS-Fehler</translation>
    </message>
    <message>
        <location filename="../core/export/session_hdf5.cpp" line="-255"/>
        <source>HDF5 could not %1</source>
        <translation>HDF5 konnte nicht: %1</translation>
    </message>
    <message>
        <location line="+31"/>
        <location line="+14"/>
        <location line="+12"/>
        <source>create attribute &apos;%1&apos;</source>
        <translation>Attribut &apos;%1&apos; anlegen</translation>
    </message>
    <message>
        <location line="-22"/>
        <location line="+12"/>
        <location line="+12"/>
        <source>write attribute &apos;%1&apos;</source>
        <translation>Attribut &apos;%1&apos; schreiben</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>set up compression for &apos;%1&apos;</source>
        <translation>Kompression für &apos;%1&apos; einrichten</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>create dataset &apos;%1&apos;</source>
        <translation>Datensatz &apos;%1&apos; anlegen</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+12"/>
        <location line="+21"/>
        <source>write dataset &apos;%1&apos;</source>
        <translation>Datensatz &apos;%1&apos; schreiben</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>create group &apos;%1&apos;</source>
        <translation>Gruppe &apos;%1&apos; anlegen</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>one row per label; frames from the sync offset and frame rate of the run</source>
        <translation>eine Zeile je Label; Bilder aus Sync-Versatz und Bildrate des Laufs</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>one row per label; no frames: the run has no video</source>
        <translation>eine Zeile je Label; keine Bilder: der Lauf hat kein Video</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>video frame index (0 = first frame); -1 outside the video</source>
        <translation>Bildindex im Video (0 = erstes Bild); -1 außerhalb des Videos</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>extreme force in the direction of motion; NaN when no sample lies in the interval</source>
        <translation>extreme Kraft in Bewegungsrichtung; NaN, wenn kein Messwert im Intervall liegt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NaN when no sample lies in the interval</source>
        <translation>NaN, wenn kein Messwert im Intervall liegt</translation>
    </message>
    <message>
        <location line="+29"/>
        <location line="+42"/>
        <source>another export is writing %1</source>
        <translation>ein anderer Export schreibt %1</translation>
    </message>
    <message>
        <location line="-41"/>
        <source>cannot create %1: %2</source>
        <translation>kann %1 nicht anlegen: %2</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>cannot create the file (is the folder writable?)</source>
        <translation>Datei kann nicht angelegt werden (ist der Ordner beschreibbar?)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>cannot create the file in memory</source>
        <translation>kann die Datei im Speicher nicht anlegen</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>flush the file</source>
        <translation>die Datei schreiben (flush)</translation>
    </message>
    <message>
        <location line="-55"/>
        <source>cannot rename the finished file into place: %1</source>
        <translation>die fertige Datei kann nicht an ihren Platz umbenannt werden: %1</translation>
    </message>
    <message>
        <location filename="../core/calibration.cpp" line="+26"/>
        <source>calibration needs at least two points, got %1</source>
        <translation>die Kalibrierung braucht mindestens zwei Punkte, erhalten: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>calibration point %1 is not a finite number</source>
        <translation>Kalibrierpunkt %1 ist keine endliche Zahl</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>calibration point %1 has a negative mass (%2 g)</source>
        <translation>Kalibrierpunkt %1 hat eine negative Masse (%2 g)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>calibration needs at least two different masses</source>
        <translation>die Kalibrierung braucht mindestens zwei verschiedene Massen</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>the voltage does not change with the mass (slope %1 V/g, standard error %2): is the sensor connected and its amplifier on?</source>
        <translation>die Spannung ändert sich nicht mit der Masse (Steigung %1 V/g, Standardfehler %2): Ist der Sensor angeschlossen und sein Verstärker eingeschaltet?</translation>
    </message>
    <message>
        <location line="+11"/>
        <location filename="../core/labels.cpp" line="-80"/>
        <location filename="../core/run_file.cpp" line="-308"/>
        <source>cannot open: %1</source>
        <translation>kann nicht geöffnet werden: %1</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>header needs columns mass_g and voltage_V</source>
        <translation>Kopfzeile braucht die Spalten mass_g und voltage_V</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>expected %1 fields, got %2</source>
        <translation>%1 Felder erwartet, %2 erhalten</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>mass_g and voltage_V must be numbers</source>
        <translation>mass_g und voltage_V müssen Zahlen sein</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>empty file (expected a header mass_g,voltage_V)</source>
        <translation>leere Datei (erwartet: Kopfzeile mass_g,voltage_V)</translation>
    </message>
    <message>
        <location filename="../core/labels.cpp" line="+24"/>
        <source>header has no &apos;%1&apos; column</source>
        <translation>Kopfzeile hat keine Spalte &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>start_s and end_s must be numbers</source>
        <translation>start_s und end_s müssen Zahlen sein</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>end_s %1 is before start_s %2</source>
        <translation>end_s %1 liegt vor start_s %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>empty label</source>
        <translation>leeres Label</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>no header row (expected track,label,start_s,end_s,comment)</source>
        <translation>keine Kopfzeile (erwartet: track,label,start_s,end_s,comment)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1: row skipped</source>
        <translation>%1: Zeile übersprungen</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>labels &apos;%1&apos; (%2 s to %3 s) and &apos;%4&apos; (%5 s to %6 s) overlap on track &apos;%7&apos;; &apos;%1&apos; is taken where they do</source>
        <translation>Labels &apos;%1&apos; (%2 s bis %3 s) und &apos;%4&apos; (%5 s bis %6 s) überlappen auf Spur &apos;%7&apos;; wo sie es tun, gilt &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../core/run_file.cpp" line="+6"/>
        <source>too large to read into memory (%1 MB)</source>
        <translation>zu groß, um in den Speicher gelesen zu werden (%1 MB)</translation>
    </message>
    <message>
        <location line="+12"/>
        <location filename="../core/session.cpp" line="+190"/>
        <source>binary data, not a text run file</source>
        <translation>Binärdaten, keine Text-Laufdatei</translation>
    </message>
    <message>
        <location filename="../core/spreadsheet_separator.cpp" line="+18"/>
        <source>the columns are separated by &apos;%1&apos;, not by commas (a spreadsheet saving in a comma-decimal language?); save it as CSV with &apos;,&apos; between columns and &apos;.&apos; in numbers</source>
        <translation>die Spalten sind durch &apos;%1&apos; getrennt, nicht durch Kommas (eine Tabellenkalkulation mit Dezimalkomma?); als CSV mit &apos;,&apos; zwischen den Spalten und &apos;.&apos; in Zahlen speichern</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>tab</source>
        <translation>Tabulator</translation>
    </message>
    <message>
        <location filename="../core/run_file.cpp" line="+51"/>
        <source>header has no &apos;%1&apos; column (found: %2)</source>
        <translation>Kopfzeile hat keine Spalte &apos;%1&apos; (gefunden: %2)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>column &apos;%1&apos; appears twice</source>
        <translation>Spalte &apos;%1&apos; kommt doppelt vor</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1: ignored unknown columns: %2</source>
        <translation>%1: unbekannte Spalten ignoriert: %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>sample row after the closing metadata</source>
        <translation>Messwertzeile nach den abschließenden Metadaten</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+26"/>
        <source>%1:%2: dropped a partial last row (recording was interrupted)</source>
        <translation>%1:%2: unvollständige letzte Zeile verworfen (Aufzeichnung wurde unterbrochen)</translation>
    </message>
    <message>
        <location line="-20"/>
        <source>expected %1 fields, found %2%3</source>
        <translation>%1 Felder erwartet, %2 gefunden%3</translation>
    </message>
    <message>
        <location line="+3"/>
        <source> (file ends mid-row: interrupted recording?)</source>
        <translation> (Datei endet mitten in einer Zeile: Aufzeichnung unterbrochen?)</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>column %1 (&apos;%2&apos;): &apos;%3&apos; is not a number</source>
        <translation>Spalte %1 (&apos;%2&apos;): &apos;%3&apos; ist keine Zahl</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>time_s %1 does not increase (previous %2)</source>
        <translation>time_s %1 steigt nicht an (vorher %2)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>file is empty</source>
        <translation>Datei ist leer</translation>
    </message>
    <message>
        <location line="+0"/>
        <location filename="../core/session.cpp" line="+19"/>
        <source>no header row</source>
        <translation>keine Kopfzeile</translation>
    </message>
    <message numerus="yes">
        <location filename="../core/run_plausibility.cpp" line="+21"/>
        <source>%1: force_N of %2 N at %3 s is beyond what any needle load cell reads (10 kN): a corrupt sample? (%n such sample(s))</source>
        <translation>
            <numerusform>%1: force_N von %2 N bei %3 s liegt jenseits dessen, was ein Nadel-Kraftsensor misst (10 kN): ein beschädigter Messpunkt? (%n solcher Messpunkt)</numerusform>
            <numerusform>%1: force_N von %2 N bei %3 s liegt jenseits dessen, was ein Nadel-Kraftsensor misst (10 kN): ein beschädigter Messpunkt? (%n solche Messpunkte)</numerusform>
        </translation>
    </message>
    <message>
        <location line="+37"/>
        <source>%1: force_N stays at %2 N from %3 s to %4 s while the needle moves %5 mm: the sensor or its amplifier saturated there, and the force beyond it is not in the file</source>
        <translation>%1: force_N bleibt von %3 s bis %4 s bei %2 N, während sich die Nadel %5 mm bewegt: Sensor oder Verstärker waren dort gesättigt, und die Kraft darüber steht nicht in der Datei</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1: position_mm spans only %2 mm: if the positions were written in metres, they are 1000 times too small (position_mm is in millimetres)</source>
        <translation>%1: position_mm umfasst nur %2 mm: wurden die Positionen in Metern geschrieben, sind sie 1000-mal zu klein (position_mm ist in Millimetern)</translation>
    </message>
    <message>
        <location filename="../core/run_file.cpp" line="+94"/>
        <source>cannot write: no space left on the disk</source>
        <translation>kann nicht schreiben: kein Platz mehr auf dem Datenträger</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>a run file is already open (%1)</source>
        <translation>eine Laufdatei ist bereits geöffnet (%1)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>another process is recording to this file; it was left untouched</source>
        <translation>ein anderer Prozess zeichnet in diese Datei auf; sie wurde nicht verändert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot lock: %1</source>
        <translation>kann nicht sperren: %1</translation>
    </message>
    <message>
        <location line="+80"/>
        <location line="+16"/>
        <source>write failed after %1 rows: %2</source>
        <translation>Schreiben nach %1 Zeilen fehlgeschlagen: %2</translation>
    </message>
    <message>
        <location filename="../core/session.cpp" line="-163"/>
        <source>not valid JSON at byte %1: %2</source>
        <translation>ungültiges JSON bei Byte %1: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>expected a JSON object</source>
        <translation>JSON-Objekt erwartet</translation>
    </message>
    <message>
        <location filename="../core/end_reason.cpp" line="+45"/>
        <source>completed</source>
        <translation>abgeschlossen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ended by operator</source>
        <translation>vom Bediener beendet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>motion stopped</source>
        <translation>Bewegung gestoppt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>emergency stop</source>
        <translation>Not-Halt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>force limit</source>
        <translation>Kraftgrenze</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stopped at puncture</source>
        <translation>bei Punktion angehalten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>device fault</source>
        <translation>Gerätefehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>write error</source>
        <translation>Schreibfehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted</source>
        <translation>unterbrochen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>aborted</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <location filename="../core/session.cpp" line="+134"/>
        <source>its name is not UTF-8, so it cannot be opened by it; rename it</source>
        <translation>sein Name ist kein UTF-8, daher lässt es sich nicht unter ihm öffnen; bitte umbenennen</translation>
    </message>
    <message>
        <location line="+66"/>
        <location line="+4"/>
        <source>cannot create the folder</source>
        <translation>Ordner kann nicht angelegt werden</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>a session already exists here; open it instead</source>
        <translation>hier gibt es bereits eine Sitzung; öffnen Sie diese stattdessen</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>not a session folder (no %1)</source>
        <translation>kein Sitzungsordner (kein %1)</translation>
    </message>
    <message>
        <location line="+186"/>
        <source>process %1 on %2</source>
        <translation>Prozess %1 auf %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>its lock file %1 names no process; if no NeedleBench has it open, delete that file</source>
        <translation>seine Sperrdatei %1 nennt keinen Prozess; wenn kein NeedleBench sie geöffnet hat, diese Datei löschen</translation>
    </message>
    <message>
        <location filename="../core/end_reason.cpp" line="+1"/>
        <source>recovered</source>
        <translation>wiederhergestellt</translation>
    </message>
    <message>
        <location filename="../core/session.cpp" line="-294"/>
        <source>unreadable</source>
        <translation>unlesbar</translation>
    </message>
    <message>
        <location filename="../core/events.cpp" line="+217"/>
        <source>too few samples before the puncture (%1) to fit the contact</source>
        <translation>zu wenige Messwerte vor dem Durchstich (%1), um den Kontakt zu fitten</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the needle does not move before the puncture</source>
        <translation>die Nadel bewegt sich vor dem Durchstich nicht</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>the contact fit failed (degenerate samples)</source>
        <translation>der Kontaktfit ist fehlgeschlagen (entartete Messwerte)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>too few samples (%1) for event detection</source>
        <translation>zu wenige Messwerte (%1) für die Ereigniserkennung</translation>
    </message>
    <message>
        <location line="+3"/>
        <location filename="../core/friction_fit.cpp" line="+616"/>
        <source>sample %1 is not a finite number</source>
        <translation>Messwert %1 ist keine endliche Zahl</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the needle does not move forward</source>
        <translation>die Nadel bewegt sich nicht vorwärts</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>no puncture: the force never rises from contact and then drops sharply (by %1 N or %2 % of its peak)</source>
        <translation>kein Durchstich: die Kraft steigt nach dem Kontakt nie an und fällt dann steil ab (um %1 N oder %2 % ihres Maximums)</translation>
    </message>
    <message>
        <location line="+68"/>
        <source>the contact label at %1 s is outside the run (%2 to %3 s)</source>
        <translation>die Kontakt-Markierung bei %1 s liegt außerhalb des Laufs (%2 bis %3 s)</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>the puncture label at %1 s is outside the run (%2 to %3 s)</source>
        <translation>die Durchstich-Markierung bei %1 s liegt außerhalb des Laufs (%2 bis %3 s)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the puncture (%1 mm) is not past the contact (%2 mm)</source>
        <translation>der Durchstich (%1 mm) liegt nicht hinter dem Kontakt (%2 mm)</translation>
    </message>
    <message>
        <location filename="../core/insertion_model.cpp" line="+16"/>
        <source>%1 time stamps for %2 positions</source>
        <translation>%1 Zeitstempel für %2 Positionen</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>the runs to compare are empty</source>
        <translation>die zu vergleichenden Läufe sind leer</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>the simulated and recorded runs do not overlap in time</source>
        <translation>simulierter und aufgezeichneter Lauf überlappen zeitlich nicht</translation>
    </message>
    <message>
        <location filename="../core/stiffness_fit.cpp" line="+156"/>
        <source>too few samples (%1) between contact and puncture</source>
        <translation>zu wenige Messwerte (%1) zwischen Kontakt und Durchstich</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>stiffness sample %1 is not a finite number</source>
        <translation>Steifigkeitsmesswert %1 ist keine endliche Zahl</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>stiffness sample %1 is %2 N: a corrupt sample</source>
        <translation>Steifigkeitsmesswert %1 ist %2 N: ein beschädigter Messwert</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>no depth past the contact point</source>
        <translation>keine Tiefe über den Kontaktpunkt hinaus</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>no runs to fit</source>
        <translation>keine Läufe zum Fitten</translation>
    </message>
    <message>
        <location filename="../core/plan.cpp" line="-898"/>
        <source>neither motion nor protocol is set</source>
        <translation>weder Bewegung noch Protokoll ist gesetzt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>motion &apos;%1&apos; does not go with protocol &apos;%2&apos; (sine motion is the friction protocol)</source>
        <translation>Bewegung &apos;%1&apos; passt nicht zu Protokoll &apos;%2&apos; (Sinusbewegung ist das Reibungsprotokoll)</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Move the slab to site %1.</source>
        <translation>Die Gewebescheibe an Stelle %1 verschieben.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Move the specimen to site %1.</source>
        <translation>Das Präparat an Stelle %1 verschieben.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Change to the %1 tip.</source>
        <translation>Auf die Spitze %1 wechseln.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mount %1.</source>
        <translation>%1 einspannen.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mount the %1 mm slab.</source>
        <translation>Die %1-mm-Gewebescheibe einspannen.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Set %1 to %2.</source>
        <translation>%1 auf %2 stellen.</translation>
    </message>
    <message>
        <location line="+108"/>
        <source>&apos;%1&apos; is not one of %2</source>
        <translation>&apos;%1&apos; ist keiner der Werte %2</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>expected a tissue name</source>
        <translation>Gewebename erwartet</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>expected a site number or name</source>
        <translation>Nummer oder Name einer Stelle erwartet</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+517"/>
        <source>expected true or false</source>
        <translation>true oder false erwartet</translation>
    </message>
    <message>
        <location line="-513"/>
        <source>expected &quot;puncture&quot; or &quot;puncture:N&quot; (N &gt;= 1)</source>
        <translation>&quot;puncture&quot; oder &quot;puncture:N&quot; (N &gt;= 1) erwartet</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+18"/>
        <source>%1 is outside %2 to %3</source>
        <translation>%1 liegt außerhalb von %2 bis %3</translation>
    </message>
    <message>
        <location line="-16"/>
        <source>expected a non-negative integer</source>
        <translation>nicht negative ganze Zahl erwartet</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+537"/>
        <source>expected a positive integer</source>
        <translation>positive ganze Zahl erwartet</translation>
    </message>
    <message>
        <location line="-532"/>
        <source>expected a positive number, got %1</source>
        <translation>positive Zahl erwartet, erhalten: %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>expected a number or a text</source>
        <translation>Zahl oder Text erwartet</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>21 insertions into whole liver 1, beveled tip, 4 mm/s (Table 2)</source>
        <translation>21 Einstiche in die ganze Leber 1, Facettenschliff, 4 mm/s (Tabelle 2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>7 insertions into liver 7 with the capsule removed, blunt tip, 2.5 mm/s (Table 3)</source>
        <translation>7 Einstiche in Leber 7 ohne Kapsel, stumpfe Spitze, 2,5 mm/s (Tabelle 3)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>liver 3 slab, sine 10 mm at 0.2/0.5/0.8 Hz at 7 locations, beveled tip (Table 4)</source>
        <translation>Scheibe aus Leber 3, Sinus 10 mm bei 0,2/0,5/0,8 Hz an 7 Stellen, Facettenschliff (Tabelle 4)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>11 insertions into whole liver 5 with video, diamond tip, 4 mm/s</source>
        <translation>11 Einstiche in die ganze Leber 5 mit Video, Diamantschliff, 4 mm/s</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>liver 7 slab with video, sine 10 mm at 0.2/0.5/0.8 Hz at 5 locations, diamond tip (Table 5)</source>
        <translation>Scheibe aus Leber 7 mit Video, Sinus 10 mm bei 0,2/0,5/0,8 Hz an 5 Stellen, Diamantschliff (Tabelle 5)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>9 insertions into a canine prostate, diamond tip, 4 mm/s</source>
        <translation>9 Einstiche in eine Hundeprostata, Diamantschliff, 4 mm/s</translation>
    </message>
    <message>
        <location line="+32"/>
        <location line="+407"/>
        <source>a factor needs at least one level</source>
        <translation>ein Faktor braucht mindestens eine Stufe</translation>
    </message>
    <message>
        <location line="-383"/>
        <source>blocked order needs a factor named site</source>
        <translation>die Reihenfolge in Blöcken braucht einen Faktor namens site</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>Fit the %1 tip.</source>
        <translation>Die Spitze %1 aufsetzen.</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 mm/s</source>
        <translation>%1 mm/s</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>amplitude %1 mm</source>
        <translation>Amplitude %1 mm</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>depth %1 mm</source>
        <translation>Tiefe %1 mm</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>site %1</source>
        <translation>Stelle %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>repeat %1</source>
        <translation>Wiederholung %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 tip</source>
        <translation>Spitze %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 cycles</source>
        <translation>%1 Zyklen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 mm slab</source>
        <translation>%1-mm-Scheibe</translation>
    </message>
    <message>
        <location line="+66"/>
        <source>redone</source>
        <translation>wiederholt</translation>
    </message>
    <message>
        <location line="+137"/>
        <location line="+21"/>
        <source>missing</source>
        <translation>fehlt</translation>
    </message>
    <message>
        <location line="-17"/>
        <source>expected a text</source>
        <translation>Text erwartet</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+57"/>
        <location line="+41"/>
        <location line="+37"/>
        <source>expected an object {...}</source>
        <translation>Objekt {...} erwartet</translation>
    </message>
    <message>
        <location line="-123"/>
        <source>expected a list [...]</source>
        <translation>Liste [...] erwartet</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&apos;%1&apos; is not an ISO 8601 date and time</source>
        <translation>&apos;%1&apos; ist kein Datum mit Uhrzeit nach ISO 8601</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&apos;%1&apos; is not a NeedleBench plan (expected %2)</source>
        <translation>&apos;%1&apos; ist kein NeedleBench-Plan (erwartet: %2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>version %1 is not supported (this program reads version %2)</source>
        <translation>Version %1 wird nicht unterstützt (dieses Programm liest Version %2)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&apos;%1&apos; is not one of listed|random|blocked</source>
        <translation>&apos;%1&apos; ist keiner der Werte listed|random|blocked</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>empty</source>
        <translation>leer</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>&apos;%1&apos; is listed twice</source>
        <translation>&apos;%1&apos; ist doppelt aufgeführt</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>unknown setting (known: %1; declare other factors under &quot;factors&quot;)</source>
        <translation>unbekannte Einstellung (bekannt: %1; weitere Faktoren unter &quot;factors&quot; angeben)</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>run %1 is listed twice</source>
        <translation>Lauf %1 ist doppelt aufgeführt</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&apos;%1&apos; is not one of pending|running|done|skipped|redone</source>
        <translation>&apos;%1&apos; ist keiner der Werte pending|running|done|skipped|redone</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>(the reason was lost by an earlier version of NeedleBench)</source>
        <translation>(der Grund ging in einer früheren Version von NeedleBench verloren)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>a run marked %1 needs the attempt that made it</source>
        <translation>ein als %1 markierter Lauf braucht den Versuch, der ihn ergab</translation>
    </message>
    <message>
        <location line="+123"/>
        <source>cannot read: %1</source>
        <translation>kann nicht gelesen werden: %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>no such file</source>
        <translation>Datei nicht vorhanden</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the file is empty; a plan is a JSON file (needlebench plan new writes one)</source>
        <translation>die Datei ist leer; ein Plan ist eine JSON-Datei (needlebench plan new schreibt eine)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>line %1</source>
        <translation>Zeile %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not JSON as a plan is written (%1)</source>
        <translation>kein JSON, wie ein Plan geschrieben ist (%1)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>expected a JSON object {...}</source>
        <translation>JSON-Objekt {...} erwartet</translation>
    </message>
    <message numerus="yes">
        <location filename="../core/excerpt.cpp" line="+31"/>
        <source>… (%n more characters)</source>
        <translation>
            <numerusform>… (%n weitere Zeichen)</numerusform>
            <numerusform>… (%n weitere Zeichen)</numerusform>
        </translation>
    </message>
    <message>
        <location line="+12"/>
        <source>… (%1 bytes in all)</source>
        <translation>… (insgesamt %1 Bytes)</translation>
    </message>
    <message>
        <location filename="../core/run_judgement.cpp" line="+47"/>
        <source>no end reason: the recording was cut off</source>
        <translation>kein Endgrund: die Aufzeichnung wurde abgeschnitten</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>unknown end reason &apos;%1&apos;</source>
        <translation>unbekannter Endgrund „%1“</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>ended early (%1)</source>
        <translation>vorzeitig beendet (%1)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>no tissue contact (the force never rose above its noise)</source>
        <translation>kein Gewebekontakt (die Kraft stieg nie über ihr Rauschen)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1 %2 %3 is %4 %3 from the median %5 %3 (limit %6 %3: %7 MADs or %8 %)</source>
        <translation>%1 %2 %3 liegt %4 %3 vom Median %5 %3 entfernt (Grenze %6 %3: %7 MADs oder %8 %)</translation>
    </message>
    <message>
        <location filename="../core/run_video_link.cpp" line="+30"/>
        <source>%1: cannot read (%2)</source>
        <translation>%1: nicht lesbar (%2)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: not a video link file (%2)</source>
        <translation>%1: keine Video-Verknüpfungsdatei (%2)</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>set by hand</source>
        <translation>von Hand gesetzt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>from marked events</source>
        <translation>aus markierten Ereignissen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>automatic</source>
        <translation>automatisch</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>not synchronised</source>
        <translation>nicht synchronisiert</translation>
    </message>
    <message>
        <location line="+92"/>
        <location line="+3"/>
        <source>cannot write (%1)</source>
        <translation>nicht schreibbar (%1)</translation>
    </message>
    <message>
        <location filename="../core/friction_fit.cpp" line="-102"/>
        <source>too few samples (%1) to find the zero-velocity band</source>
        <translation>zu wenige Messwerte (%1), um das Nullgeschwindigkeitsband zu bestimmen</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>no motion: the zero-velocity band cannot be found</source>
        <translation>keine Bewegung: das Nullgeschwindigkeitsband lässt sich nicht bestimmen</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>too few sliding samples to find the zero-velocity band</source>
        <translation>zu wenige gleitende Messwerte, um das Nullgeschwindigkeitsband zu bestimmen</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>the tissue thickness must be positive, got %1 mm</source>
        <translation>die Gewebedicke muss positiv sein, erhalten: %1 mm</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the zero-velocity band must not be negative</source>
        <translation>das Nullgeschwindigkeitsband darf nicht negativ sein</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>too few samples (%1) for a friction fit (%2 are trimmed at each end)</source>
        <translation>zu wenige Messwerte (%1) für einen Reibungsfit (an jedem Ende werden %2 abgeschnitten)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 phase names for %2 samples</source>
        <translation>%1 Phasennamen für %2 Messwerte</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 tissue velocities for %2 samples</source>
        <translation>%1 Gewebegeschwindigkeiten für %2 Messpunkte</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the tissue&apos;s velocity is measured at none of the run&apos;s samples (does the trace cover the run&apos;s time?)</source>
        <translation>die Geschwindigkeit des Gewebes ist zu keinem Messpunkt des Laufs gemessen (deckt der Verlauf die Zeit des Laufs ab?)</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>no phase c in the phases: the tissue never rested while the needle slid through it (a stroke longer than the slab&apos;s free travel gives phase c), so C and b cannot be measured</source>
        <translation>keine Phase c in den Phasen: das Gewebe kam nie zur Ruhe, während die Nadel hindurchglitt (ein Hub länger als der freie Weg der Scheibe ergibt Phase c), daher lassen sich C und b nicht messen</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>none of the %1 phase-c samples moves faster than the zero-velocity band (±%2 mm/s): in phase c as labelled the needle reaches only %3 mm/s of its %4 mm/s, so c lies only where it turns. The tissue may never have rested (a stroke within the slab&apos;s free travel carries it throughout): then C and b cannot be measured; else label c where the tissue rests while the needle is still fast</source>
        <translation>keiner der %1 Messpunkte der Phase c bewegt sich schneller als das Nullgeschwindigkeitsband (±%2 mm/s): in Phase c, wie gelabelt, erreicht die Nadel nur %3 mm/s ihrer %4 mm/s, Phase c liegt also nur dort, wo sie umkehrt. Das Gewebe kam womöglich nie zur Ruhe (ein Hub innerhalb des freien Wegs der Scheibe trägt es durchgehend mit): dann lassen sich C und b nicht messen; sonst Phase c dort labeln, wo das Gewebe ruht, während die Nadel noch schnell ist</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>none of the %1 phase-c samples moves faster than the zero-velocity band (±%2 mm/s), the needle reaching %3 mm/s in phase c: check that c is labelled where the tissue rests, or give a narrower --band-m-s</source>
        <translation>keiner der %1 Messpunkte der Phase c bewegt sich schneller als das Nullgeschwindigkeitsband (±%2 mm/s), bei bis zu %3 mm/s der Nadel in Phase c: prüfen, ob Phase c dort gelabelt ist, wo das Gewebe ruht, oder ein schmaleres --band-m-s angeben</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>phase c in one direction only (%1 sliding samples moving in, %2 moving out, of %3 phase-c samples): the tissue hardly rested in the other</source>
        <translation>Phase c nur in einer Richtung (%1 gleitende Messwerte einwärts, %2 auswärts, von %3 Messwerten der Phase c): in der anderen kam das Gewebe kaum zur Ruhe</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>motion in one direction only (%1 samples moving in, %2 moving out)</source>
        <translation>Bewegung nur in eine Richtung (%1 Messwerte einwärts, %2 auswärts)</translation>
    </message>
    <message>
        <location line="+84"/>
        <source>the friction fit is singular (velocity does not vary within a direction)</source>
        <translation>der Reibungsfit ist singulär (die Geschwindigkeit variiert innerhalb einer Richtung nicht)</translation>
    </message>
    <message>
        <location line="+153"/>
        <source>Cp &lt; 0: dynamic friction cannot push the needle along</source>
        <translation>Cp &lt; 0: Gleitreibung kann die Nadel nicht vorantreiben</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cn &lt; 0: dynamic friction cannot push the needle along</source>
        <translation>Cn &lt; 0: Gleitreibung kann die Nadel nicht vorantreiben</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bp &lt; 0: damping cannot feed energy in</source>
        <translation>bp &lt; 0: Dämpfung kann keine Energie zuführen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bn &lt; 0: damping cannot feed energy in</source>
        <translation>bn &lt; 0: Dämpfung kann keine Energie zuführen</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 = %2 ± %3 N·s/m is not determined by this run: it slides over too narrow a range of speeds</source>
        <translation>%1 = %2 ± %3 N·s/m ist durch diesen Lauf nicht bestimmt: er gleitet über einen zu engen Geschwindigkeitsbereich</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 is not determined by this run: the tissue rests on the plate only while the needle slides between %2 and %3 mm/s, of a stroke reaching %4 mm/s, too narrow a range of speeds to carry its line down to zero speed</source>
        <translation>%1 ist durch diesen Lauf nicht bestimmt: das Gewebe liegt nur an der Platte an, während die Nadel zwischen %2 und %3 mm/s gleitet, bei einem Hub bis %4 mm/s, ein zu schmaler Geschwindigkeitsbereich, um seine Gerade bis zur Geschwindigkeit null fortzuführen</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>%1 is not determined by the velocity band: in %2 of %3 stretches the force still rises where the band ends, the break-away not seen apart from the sliding (label phase a)</source>
        <translation>%1 ist durch das Geschwindigkeitsband nicht bestimmt: in %2 von %3 Abschnitten steigt die Kraft am Ende des Bandes noch, das Losbrechen ist vom Gleiten nicht zu trennen (Phase a labeln)</translation>
    </message>
    <message>
        <location line="-65"/>
        <source>%1 rests on an undetermined %2</source>
        <translation>%1 beruht auf einem unbestimmten %2</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1 and %2 are not determined by this run: its sliding force departs from the line by %3 times its noise (the tissue&apos;s give changes along the stroke)</source>
        <translation>%1 und %2 sind durch diesen Lauf nicht bestimmt: Seine Gleitkraft weicht um das %3-Fache ihres Rauschens von der Geraden ab (das Nachgeben des Gewebes ändert sich entlang des Hubs)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 and %2 are not determined by this run: letting its sliding line bend moves %1 by %3 % (the tissue&apos;s give changes with speed; label phase c where the tissue rests)</source>
        <translation>%1 und %2 sind durch diesen Lauf nicht bestimmt: Darf sich seine Gleitgerade krümmen, verschiebt sich %1 um %3 % (das Nachgeben des Gewebes ändert sich mit der Geschwindigkeit; Phase c dort markieren, wo das Gewebe ruht)</translation>
    </message>
    <message>
        <location line="-22"/>
        <source>%1 is not determined by this run: it slides only between %2 and %3 mm/s, too narrow a range of speeds to carry its line down to zero speed</source>
        <translation>%1 ist durch diesen Lauf nicht bestimmt: er gleitet nur zwischen %2 und %3 mm/s, ein zu schmaler Geschwindigkeitsbereich, um seine Gerade bis zur Geschwindigkeit null fortzuführen</translation>
    </message>
    <message>
        <location line="-270"/>
        <source>no sample moves faster than the zero-velocity band (±%1 mm/s), the needle&apos;s top speed being %2 mm/s: give a narrower --band-m-s, or label phase c</source>
        <translation>kein Messpunkt bewegt sich schneller als das Nullgeschwindigkeitsband (±%1 mm/s), bei einer Höchstgeschwindigkeit der Nadel von %2 mm/s: ein schmaleres --band-m-s angeben oder Phase c labeln</translation>
    </message>
    <message>
        <location line="+310"/>
        <source>Dp and Dn are not determined: the run has no stretch at rest (phase a) in both directions to read the static limits from</source>
        <translation>Dp und Dn sind nicht bestimmt: Der Lauf hat nicht in beiden Richtungen eine Strecke in Ruhe (Phase a), aus der sich die Haftgrenzen lesen lassen</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Dp is not positive: the static limit in + motion has the wrong sign</source>
        <translation>Dp ist nicht positiv: die Haftgrenze bei Bewegung in + hat das falsche Vorzeichen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Dn is not negative: the static limit in - motion has the wrong sign</source>
        <translation>Dn ist nicht negativ: die Haftgrenze bei Bewegung in - hat das falsche Vorzeichen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>|Dp| &lt; |Cp|: static friction below dynamic friction</source>
        <translation>|Dp| &lt; |Cp|: Haftreibung unter der Gleitreibung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>|Dn| &lt; |Cn|: static friction below dynamic friction</source>
        <translation>|Dn| &lt; |Cn|: Haftreibung unter der Gleitreibung</translation>
    </message>
    <message>
        <location filename="../core/data_names.cpp" line="-98"/>
        <source>beveled</source>
        <translation>abgeschrägt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>diamond</source>
        <translation>Diamantschliff</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>blunt</source>
        <translation>stumpf</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Liver %1</source>
        <translation>Leber %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Prostate</source>
        <translation>Prostata</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>linear</source>
        <translation>linear</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>sine</source>
        <translation>Sinus</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>insertion</source>
        <translation>Einstich</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>withdrawal</source>
        <translation>Rückzug</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>events</source>
        <translation>Ereignisse</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>motion</source>
        <translation>Bewegung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>site</source>
        <translation>Stelle</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>repeat</source>
        <translation>Wiederholung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>cycles</source>
        <translation>Zyklen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>velocity [mm/s]</source>
        <translation>Geschwindigkeit [mm/s]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>frequency [Hz]</source>
        <translation>Frequenz [Hz]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>amplitude [mm]</source>
        <translation>Amplitude [mm]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>depth [mm]</source>
        <translation>Tiefe [mm]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>slab thickness [mm]</source>
        <translation>Scheibendicke [mm]</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>contact</source>
        <translation>Kontakt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>puncture</source>
        <translation>Durchstich</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>relaxation</source>
        <translation>Relaxation</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>internal puncture</source>
        <translation>innerer Durchstich</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>all</source>
        <translation>alle</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>stiffness</source>
        <translation>Steifigkeit</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+13"/>
        <source>internal stiffness</source>
        <translation>innere Steifigkeit</translation>
    </message>
    <message>
        <location line="-11"/>
        <location line="+13"/>
        <source>friction</source>
        <translation>Reibung</translation>
    </message>
    <message>
        <location line="-11"/>
        <location line="+17"/>
        <source>prostate</source>
        <translation>Prostata</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>overall stiffness</source>
        <translation>Gesamtsteifigkeit</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>stiffness under imaging</source>
        <translation>Steifigkeit unter Bildgebung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>friction under imaging</source>
        <translation>Reibung unter Bildgebung</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>phase a</source>
        <translation>Phase a</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>velocity band</source>
        <translation>Geschwindigkeitsband</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>nominal (device)</source>
        <translation>nominal (Gerät)</translation>
    </message>
    <message>
        <location filename="../core/label_suggest.cpp" line="+238"/>
        <source>no puncture found in the force</source>
        <translation>keine Punktion in der Kraft gefunden</translation>
    </message>
    <message>
        <location filename="../core/surface_relaxation.cpp" line="+41"/>
        <source>too few frames to follow the surface</source>
        <translation>zu wenige Bilder, um der Oberfläche zu folgen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the video does not show the puncture</source>
        <translation>das Video zeigt die Punktion nicht</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>no frames near the puncture</source>
        <translation>keine Bilder nahe der Punktion</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>the surface&apos;s motion around the puncture could not be fitted</source>
        <translation>die Bewegung der Oberfläche um die Punktion ließ sich nicht anpassen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the surface&apos;s spring-back (%1 px) does not stand out of the picture&apos;s noise (%2 px)</source>
        <translation>das Zurückfedern der Oberfläche (%1 px) hebt sich nicht vom Bildrauschen (%2 px) ab</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>the video ends before the surface has come to rest</source>
        <translation>das Video endet, bevor die Oberfläche zur Ruhe gekommen ist</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the surface&apos;s motion after the puncture is not a spring-back that settles</source>
        <translation>die Bewegung der Oberfläche nach der Punktion ist kein Zurückfedern, das zur Ruhe kommt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the surface does not come to rest within %1 s</source>
        <translation>die Oberfläche kommt nicht innerhalb von %1 s zur Ruhe</translation>
    </message>
    <message>
        <location line="-18"/>
        <source>nothing springs back after the puncture: the picture goes on moving the way the needle carried it</source>
        <translation>nach der Punktion federt nichts zurück: das Bild bewegt sich weiter in die Richtung, in die die Nadel es mitgenommen hat</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>the surface springs back further (%1 px) than it was carried since the contact (%2 px): the picture lost the surface</source>
        <translation>die Oberfläche federt weiter zurück (%1 px), als sie seit dem Kontakt mitgenommen wurde (%2 px): das Bild hat die Oberfläche verloren</translation>
    </message>
    <message>
        <location filename="../core/export/kept_export.cpp" line="+33"/>
        <source>cannot keep the earlier export aside while the new one is written (cannot create %1): nothing was written</source>
        <translation>der frühere Export kann nicht beiseitegelegt werden, während der neue geschrieben wird (%1 kann nicht angelegt werden): nichts wurde geschrieben</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>cannot keep the earlier export aside while the new one is written (%1): nothing was written</source>
        <translation>der frühere Export kann nicht beiseitegelegt werden, während der neue geschrieben wird (%1): nichts wurde geschrieben</translation>
    </message>
    <message>
        <location filename="../core/tissue_trace.cpp" line="+18"/>
        <source>cannot be read: %1</source>
        <translation>kann nicht gelesen werden: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>is not a tissue trace: its first line must be &apos;%1&apos; (as labels suggest --tissue-trace writes it)</source>
        <translation>ist kein Gewebeverlauf: die erste Zeile muss &apos;%1&apos; lauten (wie labels suggest --tissue-trace sie schreibt)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>line %1 is not a time and a velocity: &apos;%2&apos;</source>
        <translation>Zeile %1 ist keine Zeit mit Geschwindigkeit: &apos;%2&apos;</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>line %1: the time %2 s does not follow %3 s</source>
        <translation>Zeile %1: die Zeit %2 s folgt nicht auf %3 s</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>holds fewer than two measurements</source>
        <translation>enthält weniger als zwei Messungen</translation>
    </message>
</context>
<context>
    <name>nb::TrDevices</name>
    <message>
        <location filename="../devices/device_spec.cpp" line="+47"/>
        <source>unknown tissue &apos;%1&apos; (%2)</source>
        <translation>unbekanntes Gewebe &apos;%1&apos; (%2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>unknown tip &apos;%1&apos; (%2)</source>
        <translation>unbekannte Spitze „%1“ (%2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>unknown setup &apos;%1&apos; (organ|platform)</source>
        <translation>unbekannter Aufbau „%1“ (organ|platform)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&apos;%1&apos;: the U6 serial number must be digits (see &apos;needlebench devices&apos;)</source>
        <translation>&apos;%1&apos;: die Seriennummer des U6 besteht aus Ziffern (siehe &apos;needlebench devices&apos;)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>unknown DAQ &apos;%1&apos; (sim | u6 | u6:SERIAL)</source>
        <translation>unbekannte Messkarte &apos;%1&apos; (sim | u6 | u6:SERIENNUMMER)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>unknown stage &apos;%1&apos; (sim | zaber:PORT)</source>
        <translation>unbekannte Achse &apos;%1&apos; (sim | zaber:PORT)</translation>
    </message>
    <message>
        <location line="+63"/>
        <source>simulated rig</source>
        <translation>simulierter Versuchsstand</translation>
    </message>
    <message>
        <location line="+24"/>
        <location filename="../devices/sim/simulated_rig.cpp" line="+52"/>
        <source>simulated load cell</source>
        <translation>simulierte Kraftmessdose</translation>
    </message>
    <message>
        <location line="+4"/>
        <location filename="../devices/sim/simulated_rig.cpp" line="-1"/>
        <source>simulated stage</source>
        <translation>simulierte Achse</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>LabJack U6 (USB bus %1 device %2)</source>
        <translation>LabJack U6 (USB-Bus %1, Gerät %2)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>USB</source>
        <translation>USB</translation>
    </message>
    <message>
        <location filename="../devices/labjack_u6/u6_force_sensor.cpp" line="+29"/>
        <source>cannot start libusb: %1</source>
        <translation>libusb kann nicht gestartet werden: %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>sending a command failed: %1</source>
        <translation>Senden eines Befehls fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>no reply for %1 ms (cable unplugged?)</source>
        <translation>keine Antwort seit %1 ms (Kabel abgezogen?)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reading a reply failed: %1</source>
        <translation>Lesen einer Antwort fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>no permission to open it (install the udev rule for 0cd5:0006)</source>
        <translation>keine Berechtigung zum Öffnen (udev-Regel für 0cd5:0006 installieren)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot open it: %1</source>
        <translation>kann nicht geöffnet werden: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>in use by another program</source>
        <translation>von einem anderen Programm belegt</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>cannot claim it: %1</source>
        <translation>kann nicht belegt werden: %1</translation>
    </message>
    <message>
        <location line="+69"/>
        <source>bus %1 device %2: %3</source>
        <translation>Bus %1 Gerät %2: %3</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>not found on USB (is it plugged in?)</source>
        <translation>am USB nicht gefunden (ist es eingesteckt?)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>reading calibration block %1: %2</source>
        <translation>Lesen des Kalibrierblocks %1: %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>calibration memory looks corrupt (gain %1 slope %2 V/count)</source>
        <translation>Kalibrierspeicher scheint beschädigt (Verstärkung %1, Steigung %2 V/Schritt)</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>unplugged (the USB device is gone)</source>
        <translation>abgezogen (das USB-Gerät ist weg)</translation>
    </message>
    <message>
        <location line="+4"/>
        <location filename="../devices/labjack_u6/u6_protocol.cpp" line="+177"/>
        <source>short reply (%1 of %2 bytes)</source>
        <translation>kurze Antwort (%1 von %2 Bytes)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>StreamStop failed with device error %1</source>
        <translation>StreamStop mit Gerätefehler %1 fehlgeschlagen</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>StreamConfig rejected with device error %1 (rate %2 Hz too high for this resolution?)</source>
        <translation>StreamConfig mit Gerätefehler %1 abgelehnt (Rate %2 Hz zu hoch für diese Auflösung?)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>StreamStart failed with device error %1</source>
        <translation>StreamStart mit Gerätefehler %1 fehlgeschlagen</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>StreamStop answered device error %1</source>
        <translation>StreamStop antwortete mit Gerätefehler %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <location filename="../devices/sim/simulated_rig.cpp" line="+145"/>
        <source>read while not streaming</source>
        <translation>Lesen ohne laufenden Stream</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>unplugged during the stream (USB device gone); samples up to %1 s were received</source>
        <translation>während des Streams abgezogen (USB-Gerät weg); Messwerte bis %1 s wurden empfangen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>stream read failed: %1</source>
        <translation>Lesen des Streams fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>USB transfer overflow</source>
        <translation>USB-Übertragungsüberlauf</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>no stream data for %1 ms (cable unplugged or device stalled?)</source>
        <translation>keine Stream-Daten seit %1 ms (Kabel abgezogen oder Gerät hängt?)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>stream transfer of %1 bytes is not whole packets; the rest is dropped</source>
        <translation>Stream-Übertragung von %1 Bytes besteht nicht aus ganzen Paketen; der Rest wird verworfen</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>dropped a stream packet: %1</source>
        <translation>ein Stream-Paket verworfen: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 corrupt stream packets in a row (%2)</source>
        <translation>%1 beschädigte Stream-Pakete in Folge (%2)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 stream packet(s) lost before packet %2 (%3 samples)</source>
        <translation>%1 Stream-Paket(e) vor Paket %2 verloren (%3 Messwerte)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>device stream buffer overflowed (backlog %1); the device is recovering</source>
        <translation>Stream-Puffer des Geräts übergelaufen (Rückstand %1); das Gerät erholt sich</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>device recovered from an overflow; %1 samples were lost</source>
        <translation>Gerät hat sich von einem Überlauf erholt; %1 Messwerte gingen verloren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>stream error %1 reported by the device</source>
        <translation>Stream-Fehler %1 vom Gerät gemeldet</translation>
    </message>
    <message>
        <location filename="../devices/labjack_u6/u6_protocol.cpp" line="+5"/>
        <source>the device reported a checksum error in our command</source>
        <translation>das Gerät meldete einen Prüfsummenfehler in unserem Befehl</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>unexpected reply header %1 %2 %3</source>
        <translation>unerwarteter Antwortkopf %1 %2 %3</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+23"/>
        <source>reply checksum mismatch</source>
        <translation>Prüfsumme der Antwort stimmt nicht</translation>
    </message>
    <message>
        <location line="-11"/>
        <source>short reply (%1 of 4 bytes)</source>
        <translation>kurze Antwort (%1 von 4 Bytes)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>unexpected reply %1 to command %2</source>
        <translation>unerwartete Antwort %1 auf Befehl %2</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>ConfigU6 failed with device error %1</source>
        <translation>ConfigU6 mit Gerätefehler %1 fehlgeschlagen</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>reading calibration failed with device error %1</source>
        <translation>Lesen der Kalibrierung mit Gerätefehler %1 fehlgeschlagen</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>short stream packet (%1 bytes)</source>
        <translation>kurzes Stream-Paket (%1 Bytes)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>not a stream data packet</source>
        <translation>kein Stream-Datenpaket</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>stream packet checksum mismatch</source>
        <translation>Prüfsumme des Stream-Pakets stimmt nicht</translation>
    </message>
    <message>
        <location filename="../devices/realtime.cpp" line="+38"/>
        <source>real-time scheduling (SCHED_FIFO) not permitted: %1; sample timing may jitter (grant rtprio in /etc/security/limits.conf or CAP_SYS_NICE)</source>
        <translation>Echtzeit-Scheduling (SCHED_FIFO) nicht erlaubt: %1; das Abtast-Timing kann schwanken (rtprio in /etc/security/limits.conf oder CAP_SYS_NICE gewähren)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>memory not locked (sanitizer build)</source>
        <translation>Speicher nicht gesperrt (Sanitizer-Build)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>memory could not be locked (mlockall: %1); page faults may delay samples</source>
        <translation>Speicher konnte nicht gesperrt werden (mlockall: %1); Seitenfehler können Messwerte verzögern</translation>
    </message>
    <message>
        <location filename="../devices/sim/imaging_render.cpp" line="+145"/>
        <source>the run has too few samples to render</source>
        <translation>der Lauf hat zu wenige Messwerte zum Zeichnen</translation>
    </message>
    <message>
        <location line="-6"/>
        <source>unknown video type &apos;.%1&apos; (use .avi, .mkv or .mp4)</source>
        <translation>unbekannter Videotyp &apos;.%1&apos; (.avi, .mkv oder .mp4 verwenden)</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>cannot write a video here (folder missing or not writable, or no encoder)</source>
        <translation>hier kann kein Video geschrieben werden (Ordner fehlt oder ist nicht beschreibbar, oder kein Encoder)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the video would start %1 s after the recording began, after its end (%2 s)</source>
        <translation>das Video begänne %1 s nach Beginn der Aufnahme, nach ihrem Ende (%2 s)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>the video could not be written</source>
        <translation>das Video konnte nicht geschrieben werden</translation>
    </message>
    <message>
        <location filename="../devices/sim/simulated_rig.cpp" line="-65"/>
        <source>no reply for 100 ms to &apos;%1&apos; (cable unplugged?)</source>
        <translation>keine Antwort seit 100 ms auf &apos;%1&apos; (Kabel abgezogen?)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>rejected &apos;%1&apos;: controller reports a fault (RJ)</source>
        <translation>&apos;%1&apos; abgelehnt: Steuerung meldet einen Fehler (RJ)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>rejected &apos;%1&apos;: driver disabled</source>
        <translation>&apos;%1&apos; abgelehnt: Treiber ausgeschaltet</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+15"/>
        <source>no reply for 100 ms (cable unplugged?)</source>
        <translation>keine Antwort seit 100 ms (Kabel abgezogen?)</translation>
    </message>
    <message>
        <location line="-13"/>
        <source>rejected &apos;driver enable&apos;: controller reports a fault (RJ)</source>
        <translation>&apos;driver enable&apos; abgelehnt: Steuerung meldet einen Fehler (RJ)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>stream start failed: LIBUSB_ERROR_IO</source>
        <translation>Start des Streams fehlgeschlagen: LIBUSB_ERROR_IO</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>stream error: USB transfer failed (LIBUSB_ERROR_IO)</source>
        <translation>Stream-Fehler: USB-Übertragung fehlgeschlagen (LIBUSB_ERROR_IO)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>no samples for %1 ms (cable unplugged?)</source>
        <translation>keine Messwerte seit %1 ms (Kabel abgezogen?)</translation>
    </message>
    <message>
        <location line="+111"/>
        <source>target %1 mm is outside the travel (%2 to %3 mm)</source>
        <translation>Ziel %1 mm liegt außerhalb des Verfahrwegs (%2 bis %3 mm)</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>unknown tissue &apos;%1&apos; (known: %2)</source>
        <translation>unbekanntes Gewebe &apos;%1&apos; (bekannt: %2)</translation>
    </message>
    <message>
        <location filename="../video/frame_index.cpp" line="+283"/>
        <location filename="../video/packet_index.cpp" line="+21"/>
        <source>no such file</source>
        <translation>Datei existiert nicht</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not a readable file</source>
        <translation>keine lesbare Datei</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the file is empty</source>
        <translation>die Datei ist leer</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>cannot open as video: %1</source>
        <translation>kann nicht als Video geöffnet werden: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>an MP4/MOV file without its index (the &apos;moov&apos; box written when a recording is closed): the recording was cut off before it was finished, and its frames cannot be found without that index</source>
        <translation>eine MP4/MOV-Datei ohne ihren Index (die &apos;moov&apos;-Box, die beim Schließen einer Aufnahme geschrieben wird): die Aufnahme wurde abgebrochen, bevor sie fertig war, und ihre Bilder lassen sich ohne diesen Index nicht finden</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>an MP4/MOV file with no video FFmpeg can read (sound only, or a video codec this system lacks)</source>
        <translation>eine MP4/MOV-Datei ohne Video, das FFmpeg lesen kann (nur Ton, oder ein Videocodec, der diesem System fehlt)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>cannot open as video (not a video file, or a format FFmpeg does not read)</source>
        <translation>kann nicht als Video geöffnet werden (keine Videodatei oder ein Format, das FFmpeg nicht liest)</translation>
    </message>
    <message>
        <location line="-213"/>
        <source>the file says its picture is turned by %1°: shown turned, as players show it</source>
        <translation>laut Datei ist das Bild um %1° gedreht: gedreht gezeigt, wie Abspielprogramme es zeigen</translation>
    </message>
    <message numerus="yes">
        <location line="-14"/>
        <source>the file&apos;s first %1 s are damaged: %n packet(s) there could not be decoded; its frames start at %1 s</source>
        <translation>
            <numerusform>die ersten %1 s der Datei sind beschädigt: %n Paket dort ließ sich nicht dekodieren; ihre Bilder beginnen bei %1 s</numerusform>
            <numerusform>die ersten %1 s der Datei sind beschädigt: %n Pakete dort ließen sich nicht dekodieren; ihre Bilder beginnen bei %1 s</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>the file is damaged between %1 s and %2 s: %n packet(s) there could not be decoded and are left out; the frames on either side are read</source>
        <translation>
            <numerusform>die Datei ist zwischen %1 s und %2 s beschädigt: %n Paket dort ließ sich nicht dekodieren und fehlt; die Bilder davor und danach werden gelesen</numerusform>
            <numerusform>die Datei ist zwischen %1 s und %2 s beschädigt: %n Pakete dort ließen sich nicht dekodieren und fehlen; die Bilder davor und danach werden gelesen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>and %n more damaged stretch(es)</source>
        <translation>
            <numerusform>und %n weitere beschädigte Stelle</numerusform>
            <numerusform>und %n weitere beschädigte Stellen</numerusform>
        </translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the file holds %1 video streams: only the first (%2x%3) is shown and measured</source>
        <translation>die Datei enthält %1 Videospuren: nur die erste (%2x%3) wird gezeigt und vermessen</translation>
    </message>
    <message>
        <location line="+277"/>
        <location filename="../video/packet_index.cpp" line="+45"/>
        <location line="+8"/>
        <source>no frame could be decoded (truncated or corrupt file?)</source>
        <translation>kein Bild konnte dekodiert werden (Datei abgeschnitten oder beschädigt?)</translation>
    </message>
    <message>
        <location line="-299"/>
        <source>only %1 of %2 frames are readable: the file is cut off, or damaged after that frame</source>
        <translation>nur %1 von %2 Bildern sind lesbar: die Datei ist abgeschnitten oder nach diesem Bild beschädigt</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>frame timestamps are not increasing: frames are reached by decoding from the start</source>
        <translation>Zeitstempel der Bilder steigen nicht an: Bilder werden durch Dekodieren vom Anfang erreicht</translation>
    </message>
    <message>
        <location filename="../video/frame_reader.cpp" line="+18"/>
        <source>the video has no indexed frames</source>
        <translation>das Video hat keine indizierten Bilder</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>cannot reopen the video (moved or deleted?)</source>
        <translation>das Video kann nicht erneut geöffnet werden (verschoben oder gelöscht?)</translation>
    </message>
    <message>
        <location line="+90"/>
        <source>frame %1 does not exist (the video has %2 frames)</source>
        <translation>Bild %1 existiert nicht (das Video hat %2 Bilder)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>frame %1 lies in a damaged stretch of the file and cannot be decoded</source>
        <translation>Bild %1 liegt in einer beschädigten Stelle der Datei und lässt sich nicht dekodieren</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>frame %1 could not be decoded (truncated or changed file?)</source>
        <translation>Bild %1 konnte nicht dekodiert werden (Datei abgeschnitten oder verändert?)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>frame %1 could not be decoded</source>
        <translation>Bild %1 konnte nicht dekodiert werden</translation>
    </message>
    <message>
        <location filename="../devices/zaber/zaber_stage.cpp" line="+54"/>
        <source>cannot open the serial port: %1</source>
        <translation>serielle Schnittstelle kann nicht geöffnet werden: %1</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Zaber stage on %1</source>
        <translation>Zaber-Achse an %1</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>ignored a garbled line: %1</source>
        <translation>unleserliche Zeile ignoriert: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>serial port failed: %1 (cable unplugged?)</source>
        <translation>serielle Schnittstelle ausgefallen: %1 (Kabel abgezogen?)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>controller fault %1: %2</source>
        <translation>Steuerungsfehler %1: %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>writing to the serial port failed: %1</source>
        <translation>Schreiben auf die serielle Schnittstelle fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>no reply to &apos;%1&apos; within %2 ms (cable unplugged or controller off?)</source>
        <translation>keine Antwort auf &apos;%1&apos; innerhalb von %2 ms (Kabel abgezogen oder Steuerung aus?)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>&apos;%1&apos; rejected: %2</source>
        <translation>&apos;%1&apos; abgelehnt: %2</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>target %1 mm is outside the travel %2..%3 mm</source>
        <translation>Ziel %1 mm liegt außerhalb des Verfahrwegs %2..%3 mm</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>speed must be positive</source>
        <translation>die Geschwindigkeit muss positiv sein</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>sine %1 mm at %2 Hz needs %3 mm/s, above the %4 mm/s limit</source>
        <translation>Sinus %1 mm bei %2 Hz braucht %3 mm/s, mehr als die Grenze von %4 mm/s</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>sine of %1 mm around %2 mm leaves the travel</source>
        <translation>Sinus von %1 mm um %2 mm verlässt den Verfahrweg</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>position reply is not a number: &apos;%1&apos;</source>
        <translation>Positionsantwort ist keine Zahl: &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../devices/interlocks.cpp" line="+22"/>
        <source>A run is recording: end it before %1.</source>
        <translation>Eine Messung läuft: Beenden Sie sie vor dem %1.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The stage is moving: stop it before %1.</source>
        <translation>Die Achse fährt: Halten Sie sie vor dem %1 an.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>The stage is not moving.</source>
        <translation>Die Achse bewegt sich nicht.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>changing the session, devices or language</source>
        <translation>Wechseln von Sitzung, Geräten oder Sprache</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>quitting</source>
        <translation>Beenden</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Device fault: %1</source>
        <translation>Gerätefehler: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The devices are not running.</source>
        <translation>Die Geräte laufen nicht.</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+73"/>
        <location line="+10"/>
        <source>Stop the motion first.</source>
        <translation>Zuerst die Bewegung stoppen.</translation>
    </message>
    <message>
        <location line="-81"/>
        <source>End the run first: disabling the drive would end the experiment unrecorded.</source>
        <translation>Zuerst den Lauf beenden: das Ausschalten des Antriebs würde das Experiment unaufgezeichnet beenden.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Bias needs the stage at rest.</source>
        <translation>Tarieren geht nur bei stehender Achse.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Biasing during a run would shift its forces; end the run first.</source>
        <translation>Tarieren während eines Laufs würde seine Kräfte verschieben; zuerst den Lauf beenden.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The force is above the noise band: bias with the needle free of tissue.</source>
        <translation>Die Kraft liegt über dem Rauschband: Tarieren Sie mit der Nadel außerhalb des Gewebes.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The needle is past the depth where it met tissue: withdraw it before biasing.</source>
        <translation>Die Nadel steckt tiefer als der Gewebekontakt: Ziehen Sie sie vor dem Tarieren zurück.</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+20"/>
        <location line="+31"/>
        <location line="+12"/>
        <source>Enable the stage first.</source>
        <translation>Zuerst die Achse einschalten.</translation>
    </message>
    <message>
        <location line="-61"/>
        <source>Zeroing needs the stage at rest.</source>
        <translation>Nullen geht nur bei stehender Achse.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Zeroing during a run would shift its positions; end the run first.</source>
        <translation>Nullen während eines Laufs würde seine Positionen verschieben; zuerst den Lauf beenden.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The needle is past the depth where it met tissue: zero with the tip at the start position.</source>
        <translation>Die Nadel steckt tiefer als der Gewebekontakt: Nullen Sie mit der Spitze in der Startposition.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The force is above the noise band: zero with the needle free of tissue.</source>
        <translation>Die Kraft liegt über dem Rauschband: Nullen Sie mit der Nadel außerhalb des Gewebes.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The motion of a run is fixed while it records or moves.</source>
        <translation>Die Bewegung eines Laufs ist festgelegt, solange er aufzeichnet oder sich bewegt.</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+33"/>
        <location line="+12"/>
        <source>Emergency stop: enable the stage again to reset it.</source>
        <translation>Not-Halt: Schalten Sie die Achse wieder ein, um ihn zurückzusetzen.</translation>
    </message>
    <message>
        <location line="-43"/>
        <source>Open or create a session first: the run needs a folder.</source>
        <translation>Zuerst eine Sitzung öffnen oder anlegen: der Lauf braucht einen Ordner.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Bias the force sensor first (needle free of tissue).</source>
        <translation>Zuerst den Kraftsensor tarieren (Nadel frei vom Gewebe).</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+31"/>
        <source>Zero the stage position first.</source>
        <translation>Zuerst die Achsposition nullen.</translation>
    </message>
    <message>
        <location line="-29"/>
        <source>No active calibration: calibrate the sensor or choose a calibration.</source>
        <translation>Keine aktive Kalibrierung: Sensor kalibrieren oder eine Kalibrierung wählen.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The calibration wizard is open: finish or close it before a run.</source>
        <translation>Der Kalibrierassistent ist geöffnet: vor einem Lauf abschließen oder schließen.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Set a maximum-force limit first.</source>
        <translation>Zuerst eine Kraftgrenze setzen.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A run is already recording: end it first.</source>
        <translation>Es wird bereits ein Lauf aufgezeichnet: zuerst beenden.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The force is %1 N, near the %2 N limit: withdraw the needle first.</source>
        <translation>Die Kraft beträgt %1 N, nahe der Grenze von %2 N: zuerst die Nadel zurückziehen.</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+40"/>
        <source>The stage is moving.</source>
        <translation>Die Achse bewegt sich.</translation>
    </message>
    <message>
        <location line="-16"/>
        <source>Jogging is never recorded: end the run first.</source>
        <translation>Tippbetrieb wird nie aufgezeichnet: Beenden Sie zuerst die Messung.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>No run is recording.</source>
        <translation>Es wird kein Lauf aufgezeichnet.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stop the motion first: End run closes the file, it does not stop the stage.</source>
        <translation>Zuerst die Bewegung stoppen: „Lauf beenden“ schließt die Datei, es hält die Achse nicht an.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Calibration changes the forces of a run; end the run first.</source>
        <translation>Eine Kalibrierung ändert die Kräfte eines Laufs; zuerst den Lauf beenden.</translation>
    </message>
    <message>
        <location filename="../devices/run_once.cpp" line="+58"/>
        <source>the devices did not get ready within %1 s</source>
        <translation>die Geräte wurden nicht innerhalb von %1 s bereit</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>interrupted before the run ended</source>
        <translation>unterbrochen, bevor die Messung endete</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the run did not finish within %1 minutes</source>
        <translation>die Messung endete nicht innerhalb von %1 Minuten</translation>
    </message>
    <message>
        <location filename="../devices/sim/simulated_devices.cpp" line="+19"/>
        <source>simulated rig (%1, %2 tip, seed %3%4)</source>
        <translation>simulierter Versuchsstand (%1, Spitze: %2, Startwert %3%4)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>, simulated clock</source>
        <translation>, simulierte Uhr</translation>
    </message>
    <message>
        <location filename="../devices/zaber/zaber_protocol.cpp" line="+96"/>
        <source>the controller is busy; try again</source>
        <translation>die Steuerung ist beschäftigt; erneut versuchen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no such axis on this controller</source>
        <translation>diese Achse gibt es an der Steuerung nicht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the controller does not know this command</source>
        <translation>die Steuerung kennt diesen Befehl nicht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a value is out of range for this stage</source>
        <translation>ein Wert liegt außerhalb des Bereichs dieser Achse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bad message id</source>
        <translation>ungültige Nachrichtenkennung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the command must be sent to the whole device</source>
        <translation>der Befehl muss an das ganze Gerät gesendet werden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the motor driver is disabled (enable it; check motor power)</source>
        <translation>der Motortreiber ist ausgeschaltet (einschalten; Motorversorgung prüfen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the controller&apos;s buffer is full</source>
        <translation>der Puffer der Steuerung ist voll</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the axis is in lockstep</source>
        <translation>die Achse ist im Gleichlauf gekoppelt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>access level too low for this setting</source>
        <translation>Zugriffsebene für diese Einstellung zu niedrig</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the axis is parked (unpark it first)</source>
        <translation>die Achse ist geparkt (zuerst entparken)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the controller is under remote control</source>
        <translation>die Steuerung wird ferngesteuert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the axis is moving</source>
        <translation>die Achse bewegt sich</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the axis has not been homed</source>
        <translation>die Achse wurde nicht referenziert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the controller reports a system error</source>
        <translation>die Steuerung meldet einen Systemfehler</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>rejected: %1</source>
        <translation>abgelehnt: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>stalled and stopped (obstruction or overload?)</source>
        <translation>blockiert und angehalten (Hindernis oder Überlast?)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>limit error</source>
        <translation>Grenzwertfehler</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>encoder error</source>
        <translation>Encoderfehler</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>driver disabled by a fault (over-temperature or power)</source>
        <translation>Treiber durch einen Fehler abgeschaltet (Übertemperatur oder Versorgung)</translation>
    </message>
    <message>
        <location filename="../video/needle_tracker.cpp" line="+778"/>
        <source>the needle line lies outside the picture</source>
        <translation>die Nadellinie liegt außerhalb des Bildes</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the needle line does not cross the region %1,%2 %3x%4 (at least 20 pixels of it)</source>
        <translation>die Nadellinie kreuzt den Bereich %1,%2 %3x%4 nicht (auf mindestens 20 Pixeln)</translation>
    </message>
    <message>
        <location filename="../video/frame_index.cpp" line="+9"/>
        <source>indexed from the file&apos;s packets: repeated pictures are not flagged as duplicates</source>
        <translation>aus den Paketen der Datei indiziert: wiederholte Bilder sind nicht als Duplikate markiert</translation>
    </message>
    <message>
        <location filename="../devices/recorder.cpp" line="+63"/>
        <source>a run is already being recorded</source>
        <translation>es wird bereits ein Lauf aufgezeichnet</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>only %1 kB free on the disk; a recording needs at least %2 kB</source>
        <translation>nur %1 kB frei auf dem Datenträger; eine Aufzeichnung braucht mindestens %2 kB</translation>
    </message>
    <message>
        <location line="+94"/>
        <source>the disk holding %1 will be full in about %2 s (%3 kB free)</source>
        <translation>der Datenträger mit %1 ist in etwa %2 s voll (%3 kB frei)</translation>
    </message>
    <message>
        <location filename="../video/tissue_tracker.cpp" line="+96"/>
        <source>the region for the tissue&apos;s motion is too small or outside the picture</source>
        <translation>der Bereich für die Bewegung des Gewebes ist zu klein oder liegt außerhalb des Bildes</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>no frame of the video could be decoded</source>
        <translation>kein Bild des Videos ließ sich dekodieren</translation>
    </message>
    <message>
        <location line="+158"/>
        <source>too few frames or samples to follow the tissue</source>
        <translation>zu wenige Bilder oder Messwerte, um dem Gewebe zu folgen</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>the needle does not move while the video runs</source>
        <translation>die Nadel bewegt sich nicht, während das Video läuft</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>nothing in the picture moves with the needle</source>
        <translation>nichts im Bild bewegt sich mit der Nadel</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>the tissue&apos;s motion does not stand out of the picture&apos;s noise</source>
        <translation>die Bewegung des Gewebes hebt sich nicht vom Bildrauschen ab</translation>
    </message>
    <message>
        <location filename="../video/labels_from_video.cpp" line="+35"/>
        <source>stopped before the video was read</source>
        <translation>angehalten, bevor das Video gelesen war</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>too few distinct frames to follow the surface</source>
        <translation>zu wenige unterschiedliche Bilder, um der Oberfläche zu folgen</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>the video gave no motion to read</source>
        <translation>das Video zeigte keine lesbare Bewegung</translation>
    </message>
</context>
<context>
    <name>nb::TrViews</name>
    <message>
        <location filename="../widgets/analysis/analysis_plots.cpp" line="+112"/>
        <source>Stiffness before puncture: %1</source>
        <translation>Steifigkeit vor dem Durchstich: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>depth past contact [mm]</source>
        <translation>Tiefe nach dem Kontakt [mm]</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+117"/>
        <location line="+58"/>
        <source>force [N]</source>
        <translation>Kraft [N]</translation>
    </message>
    <message>
        <location line="-149"/>
        <source>%1 (outlier)</source>
        <translation>%1 (Ausreißer)</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Friction against velocity: %1</source>
        <translation>Reibung über Geschwindigkeit: %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>friction force [N]</source>
        <translation>Reibungskraft [N]</translation>
    </message>
    <message>
        <location line="+125"/>
        <source>recorded</source>
        <translation>aufgezeichnet</translation>
    </message>
    <message>
        <location line="-74"/>
        <source>Karnopp fit (%1 Hz)</source>
        <translation>Karnopp-Fit (%1 Hz)</translation>
    </message>
    <message>
        <location line="-109"/>
        <location filename="../widgets/analysis/analysis_workspace.cpp" line="-705"/>
        <location line="+491"/>
        <source>no tissue given</source>
        <translation>ohne Gewebeangabe</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>pooled fit:
F = %1 x + %2 x²
(F in N, x in mm)</source>
        <translation>gemeinsame Anpassung:
F = %1 x + %2 x²
(F in N, x in mm)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>velocity [mm/s]</source>
        <translation>Geschwindigkeit [mm/s]</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>recorded, not fitted</source>
        <translation>gemessen, nicht angepasst</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>recorded, fitted</source>
        <translation>gemessen, angepasst</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Labelled phases: %1</source>
        <translation>Markierte Phasen: %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>time [s]</source>
        <translation>Zeit [s]</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>force</source>
        <translation>Kraft</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>force, insertion</source>
        <translation>Kraft, Einstechen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>force, withdrawal</source>
        <translation>Kraft, Zurückziehen</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>phase %1</source>
        <translation>Phase %1</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Model against recording: %1 (rms %2 N)</source>
        <translation>Modell gegen Aufzeichnung: %1 (RMS %2 N)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Model against recording: %1 (%2)</source>
        <translation>Modell gegen Aufzeichnung: %1 (%2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>needle position [mm]</source>
        <translation>Nadelposition [mm]</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>summed model</source>
        <translation>Summenmodell</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 by %2: mean ± std, n per level</source>
        <translation>%1 nach %2: Mittelwert ± Std.-Abw., n je Stufe</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>(none)</source>
        <translation>(keine)</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>runs</source>
        <translation>Läufe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mean ± std</source>
        <translation>Mittelwert ± Std.-Abw.</translation>
    </message>
    <message>
        <location filename="../widgets/analysis/figure_export.cpp" line="+44"/>
        <source>unknown figure format &apos;%1&apos; (png, svg or pdf)</source>
        <translation>unbekanntes Abbildungsformat &apos;%1&apos; (png, svg oder pdf)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>could not render the figure</source>
        <translation>die Abbildung konnte nicht gezeichnet werden</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>cannot write the figure</source>
        <translation>die Abbildung kann nicht geschrieben werden</translation>
    </message>
    <message>
        <location filename="../widgets/label_commands.cpp" line="+12"/>
        <source>add %1</source>
        <translation>%1 hinzufügen</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>delete %1</source>
        <translation>%1 löschen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>edit %1</source>
        <translation>%1 bearbeiten</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>split %1</source>
        <translation>%1 teilen</translation>
    </message>
</context>
<context>
    <name>nb::VideoView</name>
    <message>
        <location filename="../widgets/video_view.cpp" line="+22"/>
        <source>Open video…</source>
        <translation>Video öffnen…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>attach the video filmed during this run (or drop the file here)</source>
        <translation>das während dieses Laufs gefilmte Video anhängen (oder die Datei hierher ziehen)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>No video. Open one, or drop the file here, to review it with the force record.</source>
        <translation>Kein Video. Eines öffnen oder die Datei hierher ziehen, um es mit der Kraftaufzeichnung auszuwerten.</translation>
    </message>
    <message>
        <location line="+110"/>
        <source>frame %1   %2 s</source>
        <translation>Bild %1   %2 s</translation>
    </message>
</context>
<context>
    <name>nb::WelcomeDialog</name>
    <message>
        <location filename="../widgets/welcome_dialog.cpp" line="+17"/>
        <location line="+31"/>
        <source>Welcome to NeedleBench</source>
        <translation>Willkommen bei NeedleBench</translation>
    </message>
    <message>
        <location line="-30"/>
        <source>A session is a folder for one specimen: its calibration, its runs, their videos and labels. Start a new one or continue one.</source>
        <translation>Eine Sitzung ist ein Ordner für eine Probe: ihre Kalibrierung, ihre Läufe, deren Videos und Labels. Eine neue beginnen oder eine fortsetzen.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;New session…</source>
        <translation>&amp;Neue Sitzung…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Open session folder…</source>
        <translation>Sitzungsordner ö&amp;ffnen…</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 (not found)
%2</source>
        <translation>%1 (nicht gefunden)
%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No session is in this folder any more: moved, renamed, or on a drive not connected. Open it where it is now with Open session folder…</source>
        <translation>In diesem Ordner ist keine Sitzung mehr: verschoben, umbenannt oder auf einem nicht angeschlossenen Laufwerk. Öffnen Sie sie dort, wo sie jetzt liegt, mit „Sitzungsordner öffnen…“.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Recent sessions (double-click to open):</source>
        <translation>Zuletzt benutzte Sitzungen (Doppelklick öffnet):</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>No recent sessions.</source>
        <translation>Keine zuletzt benutzten Sitzungen.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Not now</source>
        <translation>Jetzt nicht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>look around without a session; runs need one</source>
        <translation>ohne Sitzung umsehen; Läufe brauchen eine</translation>
    </message>
</context>
<context>
    <name>nb::devices::AcquisitionEngine</name>
    <message>
        <location filename="../devices/acquisition_engine.cpp" line="+200"/>
        <source>stage enabled; fault cleared</source>
        <translation>Achse eingeschaltet; Fehler zurückgesetzt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>stage enabled; emergency stop reset</source>
        <translation>Achse eingeschaltet; Not-Halt zurückgesetzt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>stage enabled</source>
        <translation>Achse eingeschaltet</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>stage disabled</source>
        <translation>Achse ausgeschaltet</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>biasing the force sensor: averaging %1 s</source>
        <translation>Kraftsensor wird tariert: Mittelung über %1 s</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>stage position zeroed</source>
        <translation>Achsposition genullt</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>force limit must be positive (got %1 N)</source>
        <translation>die Kraftgrenze muss positiv sein (erhalten: %1 N)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>force limit %1 N</source>
        <translation>Kraftgrenze %1 N</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>withdrawal force limit must be positive (got %1 N)</source>
        <translation>die Kraftgrenze beim Zurückziehen muss positiv sein (erhalten: %1 N)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>withdrawal force limit %1 N</source>
        <translation>Kraftgrenze beim Zurückziehen %1 N</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>calibration refused: slope must be positive (got %1 V/g)</source>
        <translation>Kalibrierung abgelehnt: die Steigung muss positiv sein (erhalten: %1 V/g)</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+13"/>
        <source>calibration refused: a run is recording; end the run first</source>
        <translation>Kalibrierung abgelehnt: ein Lauf wird aufgezeichnet; beenden Sie zuerst den Lauf</translation>
    </message>
    <message>
        <location line="-8"/>
        <source>calibration &apos;%1&apos;: %2 V/g</source>
        <translation>Kalibrierung &apos;%1&apos;: %2 V/g</translation>
    </message>
    <message>
        <location line="+26"/>
        <location line="+49"/>
        <source>run not started: %1</source>
        <translation>Lauf nicht gestartet: %1</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>recording to %1</source>
        <translation>Aufzeichnung in %1</translation>
    </message>
    <message>
        <location line="+82"/>
        <source>motion stopped; still recording</source>
        <translation>Bewegung gestoppt; Aufzeichnung läuft weiter</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>motion stopped</source>
        <translation>Bewegung gestoppt</translation>
    </message>
    <message>
        <location line="+148"/>
        <source>run ended (%1): %2 samples, %3 dropped, %4</source>
        <translation>Lauf beendet (%1): %2 Messwerte, %3 verloren, %4</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>could not stop the stage: %1</source>
        <translation>die Achse konnte nicht angehalten werden: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>fault: %1</source>
        <translation>Fehler: %1</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>force limit: the load cell&apos;s reading reached the end of its input range at %1 N (%2 mm): the force may be higher; stage stopped</source>
        <translation>Kraftgrenze: die Messung des Kraftsensors erreichte das Ende seines Eingangsbereichs bei %1 N (%2 mm): die Kraft kann höher sein; Achse angehalten</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>puncture %1 at %2 mm: stage stopped</source>
        <translation>Punktion %1 bei %2 mm: Achse angehalten</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>puncture at %1 mm: slowing to %2 mm/s</source>
        <translation>Punktion bei %1 mm: verlangsamt auf %2 mm/s</translation>
    </message>
    <message>
        <location line="+69"/>
        <location line="+105"/>
        <source>warning: %1</source>
        <translation>Warnung: %1</translation>
    </message>
    <message>
        <location line="-103"/>
        <source>real-time scheduling not requested</source>
        <translation>Echtzeit-Scheduling nicht angefordert</translation>
    </message>
    <message>
        <location line="+99"/>
        <source>recording failed, stage stopped: %1</source>
        <translation>Aufzeichnung fehlgeschlagen, Verfahrtisch gestoppt: %1</translation>
    </message>
    <message>
        <location line="-219"/>
        <source>force sensor biased: V0 = %1 V (%2 samples)</source>
        <translation>Kraftsensor tariert: V0 = %1 V (%2 Messwerte)</translation>
    </message>
    <message>
        <location line="-465"/>
        <source>bias refused: %1</source>
        <translation>Tarieren abgelehnt: %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>zero refused: %1</source>
        <translation>Nullen abgelehnt: %1</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>warning: the load cell reads up to %1 N (its ±%2 V input), less than the force limit of %3 N: the stage stops there</source>
        <translation>Warnung: der Kraftsensor misst bis %1 N (sein Eingang von ±%2 V), weniger als die Kraftgrenze von %3 N: die Achse hält dort an</translation>
    </message>
    <message>
        <location line="+60"/>
        <source>a run is already on its way to its start position</source>
        <translation>eine Messung fährt bereits ihre Startposition an</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>run not started: the start position %1 mm is outside the travel (%2 to %3 mm)</source>
        <translation>Messung nicht gestartet: die Startposition %1 mm liegt außerhalb des Verfahrwegs (%2 bis %3 mm)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>moving to the start position %1 mm (not recorded)</source>
        <translation>fahre zur Startposition %1 mm (nicht aufgezeichnet)</translation>
    </message>
    <message>
        <location line="+91"/>
        <source>withdraw refused: %1</source>
        <translation>Zurückziehen abgelehnt: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>withdrawing to %1 mm; this is recorded in the open run %2</source>
        <translation>ziehe zurück auf %1 mm; dies wird in der offenen Messung %2 aufgezeichnet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>withdrawing to %1 mm (not recorded: no run open)</source>
        <translation>ziehe zurück auf %1 mm (nicht aufgezeichnet: keine Messung offen)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>move refused: %1</source>
        <translation>Fahrt abgelehnt: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>move refused: %1 mm is outside the travel (%2 to %3 mm)</source>
        <translation>Fahrt abgelehnt: %1 mm liegt außerhalb des Verfahrwegs (%2 bis %3 mm)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>moving to %1 mm (not recorded)</source>
        <translation>fahre auf %1 mm (nicht aufgezeichnet)</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>could not disable the stage after the emergency stop: %1</source>
        <translation>konnte die Achse nach dem Not-Halt nicht ausschalten: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>emergency stop: the stage is disabled until you enable it again</source>
        <translation>Not-Halt: die Achse bleibt aus, bis Sie sie wieder einschalten</translation>
    </message>
    <message>
        <location line="+171"/>
        <source>force limit: %1 N &gt; %2 N at %3 mm; stage stopped</source>
        <translation>Kraftgrenze: %1 N &gt; %2 N bei %3 mm; Achse angehalten</translation>
    </message>
</context>
</TS>

<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de">
<context>
    <name>BatteryCheck</name>
    <message>
        <source>the voltage %1 V is outside what its pack can have (%2 to %3 V)</source>
        <translation>die Spannung %1 V liegt außerhalb dessen, was sein Akku haben kann (%2 bis %3 V)</translation>
    </message>
    <message>
        <source>the charge %1 mAh is above the capacity %2 mAh</source>
        <translation>die Ladung %1 mAh liegt über der Kapazität %2 mAh</translation>
    </message>
    <message>
        <source>the charge jumped from %1 % to %2 % in %3 s</source>
        <translation>die Ladung sprang in %3 s von %1 % auf %2 %</translation>
    </message>
    <message>
        <source>Battery reading cannot be true: %1. It is left out of the gauges and plots; if it goes on, check the battery&apos;s seating and contacts.</source>
        <translation>Akkuwert kann nicht stimmen: %1. Er wird in Anzeigen und Diagrammen ausgelassen; wenn es so weitergeht, prüfen Sie Sitz und Kontakte des Akkus.</translation>
    </message>
</context>
<context>
    <name>BatteryHealth</name>
    <message>
        <source>holds %1 of the %2 mAh it claims (%3 %)</source>
        <translation>hält %1 der angegebenen %2 mAh (%3 %)</translation>
    </message>
    <message>
        <source>resistance %1 mΩ, %2 times a new pack&apos;s</source>
        <translation>Widerstand %1 mΩ, das %2-Fache eines neuen Akkus</translation>
    </message>
    <message>
        <source>it needs a drive started and stopped a few times, and part of a discharge or a charge</source>
        <translation>dafür muss der Roboter einige Male anfahren und anhalten und einen Teil einer Entladung oder Ladung durchlaufen</translation>
    </message>
    <message>
        <source>; </source>
        <translation>; </translation>
    </message>
    <message>
        <source>; capacity not measured yet</source>
        <translation>; Kapazität noch nicht gemessen</translation>
    </message>
    <message>
        <source>Good</source>
        <translation>Gut</translation>
    </message>
    <message>
        <source>Worn</source>
        <translation>Verschlissen</translation>
    </message>
    <message>
        <source>Replace</source>
        <translation>Ersetzen</translation>
    </message>
    <message>
        <source>Not measured yet</source>
        <translation>Noch nicht gemessen</translation>
    </message>
    <message>
        <source>%1 % of a cycle seen, %2 resistance samples</source>
        <translation>%1 % eines Zyklus gesehen, %2 Widerstandsmessungen</translation>
    </message>
    <message>
        <source>%1 mAh (%2)</source>
        <translation>%1 mAh (%2)</translation>
    </message>
    <message>
        <source>, </source>
        <translation>, </translation>
    </message>
    <message>
        <source>%1 %, %2 V</source>
        <translation>%1 %, %2 V</translation>
    </message>
    <message>
        <source>%1 V</source>
        <translation>%1 V</translation>
    </message>
    <message>
        <source>battery nearly flat (%1): the robot leaves Safe or Full by itself under load; charge it</source>
        <translation>Akku fast leer (%1): Der Roboter verlässt unter Last von selbst Safe oder Full; laden Sie ihn auf</translation>
    </message>
    <message>
        <source>Charging fault: the robot will not charge. Usually the charging contacts are dirty (on the robot or the dock), the supply is not the robot&apos;s own, or the pack was run deeply flat (Safe or Full left on the dock drains it). Clean the contacts, reseat the pack, then reset the charger: hold Spot and Dock together for 10 seconds, and put it back on the dock.</source>
        <translation>Ladefehler: Der Roboter lädt nicht. Meist sind die Ladekontakte verschmutzt (am Roboter oder an der Ladestation), das Netzteil ist nicht das des Roboters, oder der Akku wurde tiefentladen (Safe oder Full auf der Ladestation entlädt ihn). Reinigen Sie die Kontakte, setzen Sie den Akku neu ein und setzen Sie dann das Ladegerät zurück: Halten Sie Spot und Dock 10 Sekunden lang gleichzeitig gedrückt, und stellen Sie ihn wieder auf die Ladestation.</translation>
    </message>
    <message>
        <source>%1: %2 (%3)</source>
        <translation>%1: %2 (%3)</translation>
    </message>
    <message>
        <source>; measured %1</source>
        <translation>; gemessen %1</translation>
    </message>
    <message>
        <source>; the charge is estimated from voltage since the robot booted</source>
        <translation>; die Ladung wird seit dem Start des Roboters aus der Spannung geschätzt</translation>
    </message>
    <message>
        <source>; capacity so far: %1</source>
        <translation>; bisherige Kapazität: %1</translation>
    </message>
</context>
<context>
    <name>BitName</name>
    <message>
        <source>Advance</source>
        <translation>Advance</translation>
    </message>
    <message>
        <source>Baud Rate Change (active low)</source>
        <translation>Baudratenwechsel (low-aktiv)</translation>
    </message>
    <message>
        <source>Bump Left</source>
        <translation>Stoß links</translation>
    </message>
    <message>
        <source>Bump Right</source>
        <translation>Stoß rechts</translation>
    </message>
    <message>
        <source>Center Left</source>
        <translation>Mitte links</translation>
    </message>
    <message>
        <source>Center Right</source>
        <translation>Mitte rechts</translation>
    </message>
    <message>
        <source>Clean</source>
        <translation>Clean</translation>
    </message>
    <message>
        <source>Clock</source>
        <translation>Uhr</translation>
    </message>
    <message>
        <source>Day</source>
        <translation>Tag</translation>
    </message>
    <message>
        <source>Digital Input 0</source>
        <translation>Digitaleingang 0</translation>
    </message>
    <message>
        <source>Digital Input 1</source>
        <translation>Digitaleingang 1</translation>
    </message>
    <message>
        <source>Digital Input 2</source>
        <translation>Digitaleingang 2</translation>
    </message>
    <message>
        <source>Digital Input 3</source>
        <translation>Digitaleingang 3</translation>
    </message>
    <message>
        <source>Dock</source>
        <translation>Dock</translation>
    </message>
    <message>
        <source>Front Left</source>
        <translation>Vorne links</translation>
    </message>
    <message>
        <source>Front Right</source>
        <translation>Vorne rechts</translation>
    </message>
    <message>
        <source>Home Base</source>
        <translation>Ladestation</translation>
    </message>
    <message>
        <source>Hour</source>
        <translation>Stunde</translation>
    </message>
    <message>
        <source>Internal Charger</source>
        <translation>Internes Ladegerät</translation>
    </message>
    <message>
        <source>Left</source>
        <translation>Links</translation>
    </message>
    <message>
        <source>Left Wheel</source>
        <translation>Linkes Rad</translation>
    </message>
    <message>
        <source>Low Side Driver 0</source>
        <translation>Low-Side-Treiber 0</translation>
    </message>
    <message>
        <source>Low Side Driver 1</source>
        <translation>Low-Side-Treiber 1</translation>
    </message>
    <message>
        <source>Low Side Driver 2</source>
        <translation>Low-Side-Treiber 2</translation>
    </message>
    <message>
        <source>Main Brush</source>
        <translation>Hauptbürste</translation>
    </message>
    <message>
        <source>Minute</source>
        <translation>Minute</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Play</translation>
    </message>
    <message>
        <source>Right</source>
        <translation>Rechts</translation>
    </message>
    <message>
        <source>Right Wheel</source>
        <translation>Rechtes Rad</translation>
    </message>
    <message>
        <source>Schedule</source>
        <translation>Zeitplan</translation>
    </message>
    <message>
        <source>Side Brush</source>
        <translation>Seitenbürste</translation>
    </message>
    <message>
        <source>Spot</source>
        <translation>Spot</translation>
    </message>
    <message>
        <source>Wheel Drop Caster</source>
        <translation>Radabsenkung Stützrad</translation>
    </message>
    <message>
        <source>Wheel Drop Left</source>
        <translation>Radabsenkung links</translation>
    </message>
    <message>
        <source>Wheel Drop Right</source>
        <translation>Radabsenkung rechts</translation>
    </message>
</context>
<context>
    <name>BoundedFile</name>
    <message>
        <source>not a regular file but a named pipe</source>
        <translation>keine gewöhnliche Datei, sondern eine benannte Pipe</translation>
    </message>
    <message>
        <source>not a regular file but a folder</source>
        <translation>keine gewöhnliche Datei, sondern ein Ordner</translation>
    </message>
    <message>
        <source>not a regular file but a device</source>
        <translation>keine gewöhnliche Datei, sondern ein Gerät</translation>
    </message>
    <message>
        <source>not a regular file</source>
        <translation>keine gewöhnliche Datei</translation>
    </message>
    <message>
        <source>%1, larger than the %2 this program reads of such a file</source>
        <translation>%1, größer als die %2, die dieses Programm von einer solchen Datei liest</translation>
    </message>
    <message>
        <source>larger than the %1 this program reads of such a file</source>
        <translation>größer als die %1, die dieses Programm von einer solchen Datei liest</translation>
    </message>
    <message>
        <source>%1 bytes</source>
        <translation>%1 Bytes</translation>
    </message>
</context>
<context>
    <name>BrokerActions</name>
    <message>
        <source>Connect to &amp;broker…</source>
        <translation>Mit &amp;Broker verbinden…</translation>
    </message>
    <message>
        <source>&amp;Disconnect from broker</source>
        <translation>Vom Broker &amp;trennen</translation>
    </message>
    <message>
        <source>&amp;Fleet view	Ctrl+Shift+F</source>
        <translation>&amp;Flottenansicht	Strg+Umschalt+F</translation>
    </message>
    <message>
        <source>Fleet view — Roomba Dashboard</source>
        <translation>Flottenansicht — Roomba Dashboard</translation>
    </message>
    <message>
        <source>%1. Type the password again, or another user name.</source>
        <translation>%1. Geben Sie das Passwort erneut ein oder einen anderen Benutzernamen.</translation>
    </message>
    <message>
        <source>Connecting again to %1, the class of the last session.</source>
        <translation>Verbindung mit %1, der Klasse der letzten Sitzung, wird erneut hergestellt.</translation>
    </message>
    <message>
        <source>Last session: the class on %1 as &quot;%2&quot;. Reconnect… asks for the password.</source>
        <translation>Letzte Sitzung: die Klasse auf %1 als „%2“. Neu verbinden… fragt nach dem Passwort.</translation>
    </message>
</context>
<context>
    <name>BrokerDialog</name>
    <message>
        <source>Connect to broker</source>
        <translation>Mit Broker verbinden</translation>
    </message>
    <message>
        <source>&amp;Host:</source>
        <translation>&amp;Host:</translation>
    </message>
    <message>
        <source>&amp;Port:</source>
        <translation>&amp;Port:</translation>
    </message>
    <message>
        <source>anonymous</source>
        <translation>anonym</translation>
    </message>
    <message>
        <source>&amp;User:</source>
        <translation>&amp;Benutzer:</translation>
    </message>
    <message>
        <source>Pass&amp;word:</source>
        <translation>Pass&amp;wort:</translation>
    </message>
    <message>
        <source>&amp;Remember the password (kept in plain text in the settings)</source>
        <translation>Passwort &amp;merken (im Klartext in den Einstellungen)</translation>
    </message>
    <message>
        <source>&amp;TLS</source>
        <translation>&amp;TLS</translation>
    </message>
    <message>
        <source>the system&apos;s certificates</source>
        <translation>die Zertifikate des Systems</translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation>&amp;Durchsuchen…</translation>
    </message>
    <message>
        <source>&amp;CA file:</source>
        <translation>&amp;CA-Datei:</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Verbinden</translation>
    </message>
    <message>
        <source>CA certificate</source>
        <translation>CA-Zertifikat</translation>
    </message>
    <message>
        <source>Certificates (*.pem *.crt);;All files (*)</source>
        <translation>Zertifikate (*.pem *.crt);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Enter the broker&apos;s host name or address.</source>
        <translation>Geben Sie den Hostnamen oder die Adresse des Brokers ein.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a host name.</source>
        <translation>„%1“ ist kein Hostname.</translation>
    </message>
    <message>
        <source>A password needs a user name.</source>
        <translation>Ein Passwort braucht einen Benutzernamen.</translation>
    </message>
    <message>
        <source>The CA file %1 cannot be read.</source>
        <translation>Die CA-Datei %1 kann nicht gelesen werden.</translation>
    </message>
</context>
<context>
    <name>ByteInspector</name>
    <message>
        <source>Resume</source>
        <translation>Fortsetzen</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Stop scrolling new bytes into view; they are still recorded</source>
        <translation>Neue Bytes nicht mehr ins Bild scrollen; sie werden weiter aufgezeichnet</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Leeren</translation>
    </message>
    <message>
        <source>Forget every entry and reset the counts</source>
        <translation>Alle Einträge verwerfen und die Zähler zurücksetzen</translation>
    </message>
    <message>
        <source>Hex</source>
        <translation>Hex</translation>
    </message>
    <message>
        <source>Show bytes in hexadecimal instead of decimal</source>
        <translation>Bytes hexadezimal statt dezimal anzeigen</translation>
    </message>
    <message>
        <source>Byte log</source>
        <translation>Byte-Protokoll</translation>
    </message>
    <message>
        <source>Raw bytes to send, e.g. 128 131 or 0x80 0x83</source>
        <translation>Zu sendende Rohbytes, z. B. 128 131 oder 0x80 0x83</translation>
    </message>
    <message>
        <source>Raw bytes to send</source>
        <translation>Zu sendende Rohbytes</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>Senden</translation>
    </message>
    <message>
        <source>Check the bytes and send them to the robot</source>
        <translation>Bytes prüfen und an den Roboter senden</translation>
    </message>
    <message numerus="yes">
        <source>%Ln entry · TX %1 B · RX %2 B</source>
        <translation>
            <numerusform>%Ln Eintrag · TX %1 B · RX %2 B</numerusform>
            <numerusform>%Ln Einträge · TX %1 B · RX %2 B</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%Ln entries · TX %1 B · RX %2 B</source>
        <translation>
            <numerusform>%Ln Eintrag · TX %1 B · RX %2 B</numerusform>
            <numerusform>%Ln Einträge · TX %1 B · RX %2 B</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source> · paused, %Ln new</source>
        <translation>
            <numerusform> · angehalten, %Ln neuer</numerusform>
            <numerusform> · angehalten, %Ln neue</numerusform>
        </translation>
    </message>
    <message>
        <source> · paused</source>
        <translation> · angehalten</translation>
    </message>
    <message>
        <source>Clock time</source>
        <translation>Uhrzeit</translation>
    </message>
    <message>
        <source>Since connect</source>
        <translation>Seit Verbindung</translation>
    </message>
    <message>
        <source>Time format</source>
        <translation>Zeitformat</translation>
    </message>
    <message>
        <source>Show each entry&apos;s time of day, or the seconds since the link was opened</source>
        <translation>Zu jedem Eintrag die Uhrzeit zeigen oder die Sekunden seit dem Öffnen der Verbindung</translation>
    </message>
</context>
<context>
    <name>CalibrationDrive</name>
    <message>
        <source>The run was stopped before the end.</source>
        <translation>Die Fahrt wurde vor dem Ende angehalten.</translation>
    </message>
    <message>
        <source>A recording cannot be driven: connect to the robot.</source>
        <translation>Eine Aufzeichnung kann nicht fahren: Verbinden Sie sich mit dem Roboter.</translation>
    </message>
    <message>
        <source>The robot sends no data: connect to it and wait until it streams.</source>
        <translation>Der Roboter sendet keine Daten: Verbinden Sie sich mit ihm und warten Sie, bis er Daten sendet.</translation>
    </message>
    <message>
        <source>Say first whether this is a Roomba 500 or a Create 2: their encoders read the other way round.</source>
        <translation>Geben Sie zuerst an, ob das ein Roomba 500 oder ein Create 2 ist: Die beiden lesen ihre Encoder umgekehrt.</translation>
    </message>
    <message>
        <source>A run is already under way.</source>
        <translation>Eine Fahrt läuft schon.</translation>
    </message>
    <message>
        <source>Stopped.</source>
        <translation>Angehalten.</translation>
    </message>
    <message>
        <source>The robot did not enter Safe mode: is it on its dock, or a wheel lifted?</source>
        <translation>Der Roboter ist nicht in den Safe-Modus gegangen: Steht er auf seiner Ladestation, oder hängt ein Rad in der Luft?</translation>
    </message>
    <message>
        <source>The robot bumped into something: clear its path and run the step again.</source>
        <translation>Der Roboter ist gegen etwas gestoßen: Machen Sie den Weg frei und fahren Sie den Schritt noch einmal.</translation>
    </message>
    <message>
        <source>A cliff sensor saw a drop: move the robot away from the edge and run the step again.</source>
        <translation>Ein Abgrundsensor hat eine Kante gesehen: Stellen Sie den Roboter von der Kante weg und fahren Sie den Schritt noch einmal.</translation>
    </message>
    <message>
        <source>A wheel dropped: put the robot on the floor and run the step again.</source>
        <translation>Ein Rad ist abgesackt: Stellen Sie den Roboter auf den Boden und fahren Sie den Schritt noch einmal.</translation>
    </message>
    <message>
        <source>A cliff sensor reads a dark floor (its signal low but not near 0, no wheel dropped): move the robot to a lighter floor and run the step again.</source>
        <translation>Ein Abgrundsensor sieht einen dunklen Boden (sein Signal niedrig, aber nicht nahe 0, kein Rad abgesenkt): Stellen Sie den Roboter auf einen helleren Boden und fahren Sie den Schritt noch einmal.</translation>
    </message>
    <message>
        <source>The run did not reach its end in %1 s: the robot counted %2 of it. Is a wheel slipping or held? Check the floor and the wheels, and run the step again.</source>
        <translation>Die Fahrt hat ihr Ende in %1 s nicht erreicht: Der Roboter hat %2 davon gezählt. Rutscht ein Rad oder wird es festgehalten? Prüfen Sie Boden und Räder und fahren Sie den Schritt noch einmal.</translation>
    </message>
    <message>
        <source>The robot did not report its angle after the run: run the step again.</source>
        <translation>Der Roboter hat nach der Fahrt seinen Winkel nicht gemeldet: Fahren Sie den Schritt noch einmal.</translation>
    </message>
</context>
<context>
    <name>CalibrationWizard</name>
    <message>
        <source>Calibrate odometry: %1</source>
        <translation>Odometrie kalibrieren: %1</translation>
    </message>
    <message>
        <source>&lt; &amp;Back</source>
        <translation>&lt; &amp;Zurück</translation>
    </message>
    <message>
        <source>&amp;Next &gt;</source>
        <translation>&amp;Weiter &gt;</translation>
    </message>
    <message>
        <source>&amp;Stop</source>
        <translation>&amp;Stopp</translation>
    </message>
    <message>
        <source>Stop the robot (also Esc or Space)</source>
        <translation>Den Roboter anhalten (auch Esc oder Leertaste)</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>&amp;Schließen</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>&amp;Drive straight</source>
        <translation>&amp;Geradeaus fahren</translation>
    </message>
    <message>
        <source>from the tape, in mm</source>
        <translation>vom Maßband, in mm</translation>
    </message>
    <message>
        <source>optional: mm to the left (+) or right (-) of the line</source>
        <translation>optional: mm links (+) oder rechts (-) der Linie</translation>
    </message>
    <message>
        <source>Distance:</source>
        <translation>Strecke:</translation>
    </message>
    <message>
        <source>It really drove:</source>
        <translation>Wirklich gefahren:</translation>
    </message>
    <message>
        <source>Off the line at the end:</source>
        <translation>Am Ende neben der Linie:</translation>
    </message>
    <message>
        <source>Put the robot on a hard, clear floor with room ahead, and mark the floor under the centre of its front edge. It enters Safe mode and drives ahead by its wheel encoders, slowly, then stops. Measure with a tape from the mark to where the front edge stopped and type it in. If it ended off the straight line, say how far: that tells a left wheel from a right one.</source>
        <translation>Stellen Sie den Roboter auf einen harten, freien Boden mit Platz nach vorn und markieren Sie den Boden unter der Mitte seiner Vorderkante. Er geht in den Safe-Modus, fährt nach seinen Radencodern langsam geradeaus und hält an. Messen Sie mit dem Maßband von der Markierung bis dorthin, wo die Vorderkante stehen blieb, und geben Sie es ein. Endete er neben der geraden Linie, geben Sie an, wie weit: Daran unterscheidet sich das linke Rad vom rechten.</translation>
    </message>
    <message>
        <source> turns</source>
        <translation> Umdrehungen</translation>
    </message>
    <message>
        <source>S&amp;pin</source>
        <translation>&amp;Drehen</translation>
    </message>
    <message>
        <source>in degrees, e.g. 715</source>
        <translation>in Grad, z. B. 715</translation>
    </message>
    <message>
        <source>Spin:</source>
        <translation>Drehen:</translation>
    </message>
    <message>
        <source>It really turned:</source>
        <translation>Wirklich gedreht:</translation>
    </message>
    <message>
        <source>Mark the start heading: lay a strip of tape on the floor from the middle of the robot&apos;s front edge straight ahead, and put a piece of tape on the bumper above it. The robot spins whole turns counter-clockwise on the spot by its encoders and stops. Count the whole turns and read how far the bumper&apos;s mark is past the floor&apos;s: two turns that stop 5 degrees short are 715 degrees.</source>
        <translation>Markieren Sie die Startrichtung: Legen Sie einen Klebestreifen von der Mitte der Vorderkante des Roboters gerade nach vorn auf den Boden und kleben Sie ein Stück Band darüber auf den Stoßfänger. Der Roboter dreht sich nach seinen Encodern ganze Umdrehungen gegen den Uhrzeigersinn auf der Stelle und hält an. Zählen Sie die ganzen Umdrehungen und lesen Sie ab, wie weit die Markierung am Stoßfänger an der am Boden vorbei ist: Zwei Umdrehungen, die 5 Grad zu früh enden, sind 715 Grad.</translation>
    </message>
    <message>
        <source>&amp;Apply and keep</source>
        <translation>&amp;Übernehmen und behalten</translation>
    </message>
    <message>
        <source>&amp;Reset to the documented wheels</source>
        <translation>Auf die dokumentierten Räder &amp;zurücksetzen</translation>
    </message>
    <message>
        <source>Step 1 of 3: straight line</source>
        <translation>Schritt 1 von 3: gerade Linie</translation>
    </message>
    <message>
        <source>Step 2 of 3: turn</source>
        <translation>Schritt 2 von 3: Drehung</translation>
    </message>
    <message>
        <source>Step 3 of 3: result</source>
        <translation>Schritt 3 von 3: Ergebnis</translation>
    </message>
    <message>
        <source>Driving… Esc, Space or Stop stops it.</source>
        <translation>Fährt… Esc, Leertaste oder Stopp hält ihn an.</translation>
    </message>
    <message>
        <source>Spinning… Esc, Space or Stop stops it.</source>
        <translation>Dreht sich… Esc, Leertaste oder Stopp hält ihn an.</translation>
    </message>
    <message>
        <source>Driving… %1 of %2 mm by the encoders. Esc, Space or Stop stops it.</source>
        <translation>Fährt… %1 von %2 mm nach den Encodern. Esc, Leertaste oder Stopp hält ihn an.</translation>
    </message>
    <message>
        <source>Spinning… %1 of %2 degrees by the encoders. Esc, Space or Stop stops it.</source>
        <translation>Dreht sich… %1 von %2 Grad nach den Encodern. Esc, Leertaste oder Stopp hält ihn an.</translation>
    </message>
    <message>
        <source>Stopped after %1 mm by the encoders. Now measure what it really drove.</source>
        <translation>Nach %1 mm laut Encodern angehalten. Messen Sie jetzt, wie weit er wirklich gefahren ist.</translation>
    </message>
    <message>
        <source>Stopped after %1 mm by the encoders. This is a virtual robot: the measurements below come from its true position in the room, %2 mm from the start and %3 mm off the line.</source>
        <translation>Nach %1 mm laut Encodern angehalten. Das ist ein virtueller Roboter: Die Messwerte unten kommen von seiner wahren Position im Raum, %2 mm vom Start und %3 mm neben der Linie.</translation>
    </message>
    <message>
        <source>Stopped after %1 degrees by the encoders. Now read how far it really turned.</source>
        <translation>Nach %1 Grad laut Encodern angehalten. Lesen Sie jetzt ab, wie weit er sich wirklich gedreht hat.</translation>
    </message>
    <message>
        <source>Stopped after %1 degrees by the encoders. This is a virtual robot: the angle below comes from its true heading in the room, %2 degrees.</source>
        <translation>Nach %1 Grad laut Encodern angehalten. Das ist ein virtueller Roboter: Der Winkel unten kommt von seiner wahren Richtung im Raum, %2 Grad.</translation>
    </message>
    <message>
        <source>%1 Nothing was measured; run the step again.</source>
        <translation>%1 Es wurde nichts gemessen; fahren Sie den Schritt noch einmal.</translation>
    </message>
    <message>
        <source>%1: “%2” is not a number. Type what you measured, in %3.</source>
        <translation>%1: „%2“ ist keine Zahl. Geben Sie ein, was Sie gemessen haben, in %3.</translation>
    </message>
    <message>
        <source>%1: %2 %3 cannot be. Type what you measured, more than 0 %3.</source>
        <translation>%1: %2 %3 kann nicht sein. Geben Sie ein, was Sie gemessen haben, mehr als 0 %3.</translation>
    </message>
    <message>
        <source>%1: %2 %3 is more than 50 % off the %4 %3 the encoders counted. Measure again: a typing slip, or a wheel that slipped?</source>
        <translation>%1: %2 %3 liegt mehr als 50 % neben den %4 %3, die die Encoder gezählt haben. Messen Sie noch einmal: ein Tippfehler, oder ist ein Rad durchgerutscht?</translation>
    </message>
    <message>
        <source>Drive the straight line, the turn or both first.</source>
        <translation>Fahren Sie zuerst die gerade Linie, die Drehung oder beides.</translation>
    </message>
    <message>
        <source>Measured distance</source>
        <translation>Gemessene Strecke</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <source>Off the line: “%1” is not a distance in mm less than half the run; leave it empty if you did not measure it.</source>
        <translation>Neben der Linie: „%1“ ist keine Strecke in mm unter der halben Fahrt; lassen Sie das Feld leer, wenn Sie sie nicht gemessen haben.</translation>
    </message>
    <message>
        <source>Straight line: the distance packet (19) says %1 mm, the encoders %2 mm%3.</source>
        <translation>Gerade Linie: Das Streckenpaket (19) sagt %1 mm, die Encoder %2 mm%3.</translation>
    </message>
    <message>
        <source>: they disagree</source>
        <translation>: Sie stimmen nicht überein</translation>
    </message>
    <message>
        <source>Measured angle</source>
        <translation>Gemessener Winkel</translation>
    </message>
    <message>
        <source>degrees</source>
        <translation>Grad</translation>
    </message>
    <message>
        <source>Turn: the angle packet (20) says %1 degrees, the encoders %2 degrees%3.</source>
        <translation>Drehung: Das Winkelpaket (20) sagt %1 Grad, die Encoder %2 Grad%3.</translation>
    </message>
    <message>
        <source>These runs cannot be right: %1</source>
        <translation>Diese Fahrten können nicht stimmen: %1</translation>
    </message>
    <message>
        <source>This robot&apos;s firmware reports its own packets wrongly (Robot → Read firmware version… names it). The map uses the encoders.</source>
        <translation>Die Firmware dieses Roboters meldet ihre eigenen Pakete falsch (Roboter → Firmware-Version lesen… nennt sie). Die Karte verwendet die Encoder.</translation>
    </message>
    <message>
        <source>Firmware %1 reports its own packets wrongly. The map uses the encoders.</source>
        <translation>Die Firmware %1 meldet ihre eigenen Pakete falsch. Die Karte verwendet die Encoder.</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;Left wheel&lt;/b&gt; %1 mm (%2 × the documented 72 mm), &lt;b&gt;right wheel&lt;/b&gt; %3 mm (%4 ×)%5.&lt;br&gt;&lt;b&gt;Wheel base&lt;/b&gt; %6 mm (documented 235 mm).&lt;/p&gt;&lt;p&gt;A 1 m square driven by the encoders, predicted from these runs: &lt;b&gt;%7 mm&lt;/b&gt; from its start with the wheels counted now, &lt;b&gt;%8 mm&lt;/b&gt; with these.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Linkes Rad&lt;/b&gt; %1 mm (%2 × die dokumentierten 72 mm), &lt;b&gt;rechtes Rad&lt;/b&gt; %3 mm (%4 ×)%5.&lt;br&gt;&lt;b&gt;Radabstand&lt;/b&gt; %6 mm (dokumentiert 235 mm).&lt;/p&gt;&lt;p&gt;Ein nach den Encodern gefahrenes 1-m-Quadrat, aus diesen Fahrten vorhergesagt: &lt;b&gt;%7 mm&lt;/b&gt; von seinem Start mit den jetzt gezählten Rädern, &lt;b&gt;%8 mm&lt;/b&gt; mit diesen.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>: the two wheels differ</source>
        <translation>: Die beiden Räder sind verschieden</translation>
    </message>
    <message>
        <source>%1 is counted with the documented wheels: 72 mm, 235 mm apart.</source>
        <translation>%1 wird mit den dokumentierten Rädern gezählt: 72 mm, 235 mm Abstand.</translation>
    </message>
    <message>
        <source>%1 is counted with wheels of %2 mm (left) and %3 mm (right), %4 mm apart, measured on %5.</source>
        <translation>%1 wird mit Rädern von %2 mm (links) und %3 mm (rechts) und %4 mm Abstand gezählt, gemessen am %5.</translation>
    </message>
</context>
<context>
    <name>CalibrationWizardAction</name>
    <message>
        <source>&amp;Calibrate odometry…</source>
        <translation>Odometrie &amp;kalibrieren…</translation>
    </message>
    <message>
        <source>Measure the selected robot&apos;s real wheels, so that its map stops drifting</source>
        <translation>Die wirklichen Räder des ausgewählten Roboters messen, damit seine Karte nicht mehr abdriftet</translation>
    </message>
</context>
<context>
    <name>ChannelChooser</name>
    <message>
        <source>Bumps &amp; cliffs</source>
        <translation>Stöße &amp; Abgründe</translation>
    </message>
    <message>
        <source>Battery</source>
        <translation>Akku</translation>
    </message>
    <message>
        <source>Motion</source>
        <translation>Bewegung</translation>
    </message>
    <message>
        <source>Light bumpers</source>
        <translation>Lichtstoßfänger</translation>
    </message>
    <message>
        <source>Motors &amp; dirt</source>
        <translation>Motoren &amp; Schmutz</translation>
    </message>
    <message>
        <source>Cargo bay</source>
        <translation>Laderaum</translation>
    </message>
    <message>
        <source>IR, buttons &amp; mode</source>
        <translation>IR, Tasten &amp; Modus</translation>
    </message>
    <message>
        <source>Unused</source>
        <translation>Unbenutzt</translation>
    </message>
    <message>
        <source>Choose channels</source>
        <translation>Kanäle wählen</translation>
    </message>
    <message>
        <source>Choose the sensor packets this plot shows</source>
        <translation>Sensorpakete wählen, die dieses Diagramm zeigt</translation>
    </message>
    <message numerus="yes">
        <source>Channels (%n)</source>
        <translation>
            <numerusform>Kanäle (%n)</numerusform>
            <numerusform>Kanäle (%n)</numerusform>
        </translation>
    </message>
    <message>
        <source>plain numbers</source>
        <translation>reine Zahlen</translation>
    </message>
    <message>
        <source>This plot&apos;s axes show %1 and %2: add a plot for %3</source>
        <translation>Die Achsen dieses Diagramms zeigen %1 und %2: fügen Sie für %3 ein Diagramm hinzu</translation>
    </message>
</context>
<context>
    <name>CommandDecoder</name>
    <message>
        <source> (straight)</source>
        <translation> (geradeaus)</translation>
    </message>
    <message>
        <source> (turn in place clockwise)</source>
        <translation> (auf der Stelle drehen, im Uhrzeigersinn)</translation>
    </message>
    <message>
        <source> (turn in place counter-clockwise)</source>
        <translation> (auf der Stelle drehen, gegen den Uhrzeigersinn)</translation>
    </message>
    <message>
        <source>group %1 (packets %2..%3)</source>
        <translation>Gruppe %1 (Pakete %2..%3)</translation>
    </message>
    <message>
        <source>packet %1 (not on the %2)</source>
        <translation>Paket %1 (nicht beim %2)</translation>
    </message>
    <message>
        <source>not a command of the %1</source>
        <translation>kein Befehl des %1</translation>
    </message>
    <message>
        <source>%1, incomplete: its count byte is missing</source>
        <translation>%1, unvollständig: das Anzahlbyte fehlt</translation>
    </message>
    <message>
        <source>%1, incomplete: %2 of %3 data bytes</source>
        <translation>%1, unvollständig: %2 von %3 Datenbytes</translation>
    </message>
    <message>
        <source>rest</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>%1 slot %2, %3%4</source>
        <translation>%1 Platz %2, %3%4</translation>
    </message>
    <message numerus="yes">
        <source>%n byte</source>
        <translation>
            <numerusform>%n Byte</numerusform>
            <numerusform>%n Bytes</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n bytes</source>
        <translation>
            <numerusform>%n Byte</numerusform>
            <numerusform>%n Bytes</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 code %2%3</source>
        <translation>%1 Code %2%3</translation>
    </message>
    <message>
        <source>%1 velocity %2 radius %3%4</source>
        <translation>%1 Geschwindigkeit %2 Radius %3%4</translation>
    </message>
    <message>
        <source>pause</source>
        <translation>anhalten</translation>
    </message>
    <message>
        <source>resume</source>
        <translation>fortsetzen</translation>
    </message>
    <message>
        <source>state %1</source>
        <translation>Zustand %1</translation>
    </message>
    <message>
        <source>%1 off</source>
        <translation>%1 aus</translation>
    </message>
    <message>
        <source>Type the bytes to send, for example 128 131 or 0x80 0x83.</source>
        <translation>Geben Sie die zu sendenden Bytes ein, zum Beispiel 128 131 oder 0x80 0x83.</translation>
    </message>
    <message>
        <source>Byte %1: “%2” is not a number.</source>
        <translation>Byte %1: „%2“ ist keine Zahl.</translation>
    </message>
    <message>
        <source>Byte %1: %2 is outside 0..255.</source>
        <translation>Byte %1: %2 liegt außerhalb von 0..255.</translation>
    </message>
    <message>
        <source>Byte %1: %2 is not an opcode of the %3.</source>
        <translation>Byte %1: %2 ist kein Opcode des %3.</translation>
    </message>
    <message>
        <source>%1 needs its song number and length bytes.</source>
        <translation>%1 braucht die Bytes für Liednummer und Länge.</translation>
    </message>
    <message>
        <source>%1 needs its count byte.</source>
        <translation>%1 braucht das Anzahlbyte.</translation>
    </message>
    <message>
        <source>%1 takes %2 data bytes; got %3.</source>
        <translation>%1 erwartet %2 Datenbytes, erhalten: %3.</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message numerus="yes">
        <source>%n note</source>
        <translation>
            <numerusform>%n Note</numerusform>
            <numerusform>%n Noten</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n notes</source>
        <translation>
            <numerusform>%n Note</numerusform>
            <numerusform>%n Noten</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n packet</source>
        <translation>
            <numerusform>%n Paket</numerusform>
            <numerusform>%n Pakete</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n packets</source>
        <translation>
            <numerusform>%n Paket</numerusform>
            <numerusform>%n Pakete</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ComparisonBar</name>
    <message>
        <source>Compared with %1</source>
        <translation>Verglichen mit %1</translation>
    </message>
    <message>
        <source>aligned at the start</source>
        <translation>am Anfang ausgerichtet</translation>
    </message>
    <message>
        <source>aligned at “%1”</source>
        <translation>an „%1“ ausgerichtet</translation>
    </message>
    <message>
        <source>Where the two runs line up in time: their starts, or a marker both hold</source>
        <translation>Wo die beiden Fahrten zeitlich übereinanderliegen: an ihren Anfängen oder an einer Markierung, die beide haben</translation>
    </message>
    <message>
        <source>Close comparison</source>
        <translation>Vergleich schließen</translation>
    </message>
</context>
<context>
    <name>ConnectionBar</name>
    <message>
        <source>Virtual robot</source>
        <translation>Virtueller Roboter</translation>
    </message>
    <message>
        <source>Serial port</source>
        <translation>Serieller Port</translation>
    </message>
    <message>
        <source>TCP (ser2net)</source>
        <translation>TCP (ser2net)</translation>
    </message>
    <message>
        <source>Transport</source>
        <translation>Verbindungsart</translation>
    </message>
    <message>
        <source>/dev/ttyUSB0 or a typed path</source>
        <translation>/dev/ttyUSB0 oder ein eingegebener Pfad</translation>
    </message>
    <message>
        <source>List the serial ports again</source>
        <translation>Serielle Ports neu auflisten</translation>
    </message>
    <message>
        <source>host:port, e.g. raspberrypi:3333</source>
        <translation>host:port, z. B. raspberrypi:3333</translation>
    </message>
    <message>
        <source>TCP bridge</source>
        <translation>TCP-Brücke</translation>
    </message>
    <message>
        <source>Auto</source>
        <translation>Auto</translation>
    </message>
    <message>
        <source>Robot profile</source>
        <translation>Roboterprofil</translation>
    </message>
    <message>
        <source>Default baud</source>
        <translation>Standard-Baudrate</translation>
    </message>
    <message>
        <source>Baud rate</source>
        <translation>Baudrate</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Verbinden</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>Trennen</translation>
    </message>
    <message>
        <source>Choose a serial port or type its path.</source>
        <translation>Wählen Sie einen seriellen Port oder geben Sie seinen Pfad ein.</translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation>Aktualisieren</translation>
    </message>
    <message>
        <source>Disconnect to change the port</source>
        <translation>Trennen, um den Anschluss zu ändern</translation>
    </message>
    <message>
        <source>Wake line</source>
        <translation>Weckleitung</translation>
    </message>
    <message>
        <source>Wake: RTS</source>
        <translation>Wecken: RTS</translation>
    </message>
    <message>
        <source>Wake: DTR</source>
        <translation>Wecken: DTR</translation>
    </message>
    <message>
        <source>Wake: both</source>
        <translation>Wecken: beide</translation>
    </message>
    <message>
        <source>Wake: none</source>
        <translation>Wecken: keine</translation>
    </message>
    <message>
        <source>The adapter&apos;s line wired to the robot&apos;s BRC pin, pulsed to wake it and keep it awake. Many cables use RTS, some DTR; both pulses the two; none: the cable has no BRC wire.</source>
        <translation>Die Leitung des Adapters, die mit dem BRC-Pin des Roboters verbunden ist; sie wird gepulst, um ihn zu wecken und wach zu halten. Viele Kabel nutzen RTS, manche DTR; beide pulst die zwei; keine: Das Kabel hat keine BRC-Ader.</translation>
    </message>
    <message>
        <source>Wake</source>
        <translation>Wecken</translation>
    </message>
    <message>
        <source>Pulse the robot&apos;s BRC pin: switches on a robot switched off at its power button</source>
        <translation>Pulst den BRC-Pin des Roboters: schaltet einen Roboter ein, der an seiner Ein/Aus-Taste ausgeschaltet wurde</translation>
    </message>
</context>
<context>
    <name>ConnectionCheckup</name>
    <message>
        <source>Which robot is this?</source>
        <translation>Welcher Roboter ist das?</translation>
    </message>
    <message>
        <source>Roomba 500</source>
        <translation>Roomba 500</translation>
    </message>
    <message>
        <source>%1 on %2</source>
        <translation>%1 an %2</translation>
    </message>
    <message>
        <source>%1 is a Roomba 500 or a Create 2, and the two answer every question alike.

The Roomba 500 is the cleaning robot of the 500 series. The Create 2 is iRobot&apos;s educational robot, built on the Roomba 600 (a Roomba 600 counts as a Create 2).

The choice decides how the wheel counts are read: the wrong one mirrors every turn on the map. Until you choose, the map draws no path for this robot. The answer is kept for this robot; the profile in the connection bar changes it later.</source>
        <translation>%1 ist ein Roomba 500 oder ein Create 2, und beide antworten auf jede Frage gleich.

Der Roomba 500 ist der Staubsaugerroboter der 500er-Serie. Der Create 2 ist der Lernroboter von iRobot, gebaut auf dem Roomba 600 (ein Roomba 600 gilt als Create 2).

Die Wahl entscheidet, wie die Radzähler gelesen werden: Die falsche spiegelt jede Drehung auf der Karte. Bis Sie wählen, zeichnet die Karte für diesen Roboter keinen Weg. Die Antwort wird für diesen Roboter gespeichert; das Profil in der Verbindungsleiste ändert sie später.</translation>
    </message>
    <message>
        <source>Create 2 / Roomba 600</source>
        <translation>Create 2 / Roomba 600</translation>
    </message>
</context>
<context>
    <name>ConnectionNextSteps</name>
    <message>
        <source>No serial port is on this computer: plug the robot&apos;s cable in, then choose its port in the connection bar.</source>
        <translation>Dieser Computer hat keinen seriellen Anschluss: Stecken Sie das Kabel des Roboters ein und wählen Sie dann seinen Anschluss in der Verbindungsleiste.</translation>
    </message>
    <message>
        <source>%1 does not exist. The serial ports on this computer: %2. Choose one in the connection bar.</source>
        <translation>%1 gibt es nicht. Die seriellen Anschlüsse dieses Computers: %2. Wählen Sie einen in der Verbindungsleiste.</translation>
    </message>
    <message>
        <source>This user may not open %1: add yourself to the group %2 (sudo adduser $USER %2), then log out and in again.</source>
        <translation>Dieser Benutzer darf %1 nicht öffnen: Fügen Sie sich der Gruppe %2 hinzu (sudo adduser $USER %2), melden Sie sich dann ab und wieder an.</translation>
    </message>
    <message>
        <source>Check that the bridge at %1:%2 is on and on this network, and that ser2net (or the Wi-Fi serial module) listens on that port.</source>
        <translation>Prüfen Sie, ob die Brücke unter %1:%2 eingeschaltet und in diesem Netz ist und ob ser2net (oder das WLAN-Seriell-Modul) an diesem Port lauscht.</translation>
    </message>
    <message>
        <source>Over raw TCP the bridge&apos;s serial rate is fixed in its own settings: it must be the robot&apos;s rate (115200 for a Roomba 500 or Create 2, 57600 for a Create).</source>
        <translation>Über reines TCP ist die serielle Rate der Brücke in ihren eigenen Einstellungen festgelegt: Sie muss die Rate des Roboters sein (115200 für einen Roomba 500 oder Create 2, 57600 für einen Create).</translation>
    </message>
    <message>
        <source>Bytes come back but make no sense at any rate: check that the cable is a robot&apos;s serial cable (5 V TTL, not RS-232) and that nothing else uses the port.</source>
        <translation>Es kommen Bytes zurück, die bei keiner Rate Sinn ergeben: Prüfen Sie, ob das Kabel ein serielles Roboterkabel ist (5 V TTL, nicht RS-232) und ob nichts anderes den Anschluss benutzt.</translation>
    </message>
    <message>
        <source>Check that the robot is switched on (its power light is lit) and that its cable is firmly in; a robot asleep on its dock wakes when it is taken off.</source>
        <translation>Prüfen Sie, ob der Roboter eingeschaltet ist (seine Betriebsleuchte leuchtet) und sein Kabel fest steckt; ein auf seiner Station schlafender Roboter wacht auf, wenn man ihn herunternimmt.</translation>
    </message>
    <message>
        <source>Then press Connect to try again.</source>
        <translation>Drücken Sie dann Verbinden, um es erneut zu versuchen.</translation>
    </message>
    <message>
        <source>No port is chosen. The serial ports on this computer: %1. Choose one in the connection bar.</source>
        <translation>Kein Anschluss gewählt. Die seriellen Anschlüsse dieses Computers: %1. Wählen Sie einen in der Verbindungsleiste.</translation>
    </message>
</context>
<context>
    <name>DashboardCommandLine</name>
    <message>
        <source>%1 needs a value; see --help</source>
        <translation>%1 braucht einen Wert; siehe --help</translation>
    </message>
    <message>
        <source>choose one of --sim, --port, --tcp and --replay</source>
        <translation>nur eine der Optionen --sim, --port, --tcp und --replay angeben</translation>
    </message>
    <message>
        <source>--record: the folder of &apos;%1&apos; does not exist</source>
        <translation>--record: der Ordner von „%1“ existiert nicht</translation>
    </message>
    <message>
        <source>unknown language &apos;%1&apos; (%2)</source>
        <translation>unbekannte Sprache „%1“ (%2)</translation>
    </message>
    <message>
        <source>unknown argument &apos;%1&apos;; see --help</source>
        <translation>unbekanntes Argument „%1“; siehe --help</translation>
    </message>
    <message>
        <source>--replay reads the profile and baud from the recording; leave out --profile, --baud and --brc-line</source>
        <translation>--replay liest Profil und Baudrate aus der Aufzeichnung; --profile, --baud und --brc-line weglassen</translation>
    </message>
    <message>
        <source>--record records a robot; a replay is already a recording</source>
        <translation>--record zeichnet einen Roboter auf; eine Wiedergabe ist bereits eine Aufzeichnung</translation>
    </message>
    <message>
        <source>cannot replay %1</source>
        <translation>%1 kann nicht wiedergegeben werden</translation>
    </message>
    <message>
        <source>--sim takes 1 to %1 robots, not %2</source>
        <translation>--sim nimmt 1 bis %1 Roboter, nicht %2</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a size in mm within half of the documents&apos; %3 mm</source>
        <translation>%1: „%2“ ist keine Größe in mm innerhalb der Hälfte der dokumentierten %3 mm</translation>
    </message>
    <message>
        <source>--wheel-diameter, --left-wheel-diameter, --right-wheel-diameter and --wheel-base go with --sim</source>
        <translation>--wheel-diameter, --left-wheel-diameter, --right-wheel-diameter und --wheel-base gehören zu --sim</translation>
    </message>
    <message>
        <source>Usage: roomba-dashboard [--sim [N] | --port PATH | --tcp HOST:PORT | --replay FILE]
                        [--profile P] [--baud N] [--brc-line LINE] [--record FILE]
                        [--lang CODE]
                        [--foxglove [[ADDRESS:]PORT]]

  --sim [N]          the built-in virtual robot, or N of them (up to %2) in one room
  --port PATH        a serial port, USB adapter or pseudo-terminal
  --tcp HOST:PORT    a serial-over-TCP bridge such as ser2net
  --replay FILE      play back a recording (.oirec) as if it were the robot
  --profile P        roomba500, create2 (also roomba600), create1 (also create) or auto
  --baud N           the line speed; the profile&apos;s default when left out
  --brc-line LINE    the wake line: the adapter&apos;s line wired to the robot&apos;s BRC pin,
                     pulsed to wake it and keep it awake: rts (default), dtr, both,
                     or none (the cable has no BRC wire: no pulse is tried)
  --record FILE      record every byte to and from the robot into FILE
  --lang CODE        the language of the window: %1
  --foxglove [[ADDRESS:]PORT]  serve the robots live to Foxglove, Lichtblick and
                     PlotJuggler (Foxglove WebSocket protocol) on ADDRESS (default
                     127.0.0.1, this computer only) and PORT (default 8765)
  --wheel-diameter MM, --left-wheel-diameter MM, --right-wheel-diameter MM,
  --wheel-base MM    with --sim: the virtual robot&apos;s real wheels (documents: 72
                     and 235 mm), so that its odometry drifts as a real one&apos;s
                     does, to practise Robot &gt; Calibrate odometry
  --help, --version

Without a connection option the dashboard reconnects the robots it had last,
or on first start the virtual robot; with one, it holds just that robot (or
those virtual robots) and keeps the saved list for next time. Shift+Esc stops
every robot. Without --lang it speaks the language chosen in its View menu,
or the system&apos;s.
</source>
        <translation>Aufruf: roomba-dashboard [--sim [N] | --port PFAD | --tcp HOST:PORT | --replay DATEI]
                         [--profile P] [--baud N] [--brc-line LEITUNG] [--record DATEI]
                         [--lang CODE]
                         [--foxglove [[ADRESSE:]PORT]]

  --sim [N]          der eingebaute virtuelle Roboter, oder N davon (bis %2) in einem Raum
  --port PFAD        ein serieller Port, USB-Adapter oder Pseudo-Terminal
  --tcp HOST:PORT    eine Seriell-über-TCP-Brücke wie ser2net
  --replay DATEI     eine Aufzeichnung (.oirec) abspielen, als wäre sie der Roboter
  --profile P        roomba500, create2 (auch roomba600), create1 (auch create) oder auto
  --baud N           die Leitungsgeschwindigkeit; ohne Angabe die Vorgabe des Profils
  --brc-line LEITUNG die Weckleitung: die Leitung des Adapters am BRC-Pin des Roboters,
                     gepulst, um ihn zu wecken und wach zu halten: rts (Vorgabe), dtr, both
                     oder none (das Kabel hat keinen BRC-Draht: kein Impuls)
  --record DATEI     jedes Byte zum und vom Roboter in DATEI aufzeichnen
  --lang CODE        die Sprache des Fensters: %1
  --foxglove [[ADRESSE:]PORT]  die Roboter live für Foxglove, Lichtblick und
                     PlotJuggler bereitstellen (Foxglove-WebSocket-Protokoll) auf ADRESSE
                     (Vorgabe 127.0.0.1, nur dieser Computer) und PORT (Vorgabe 8765)
  --wheel-diameter MM, --left-wheel-diameter MM, --right-wheel-diameter MM,
  --wheel-base MM    mit --sim: die wirklichen Räder des virtuellen Roboters
                     (Dokumente: 72 und 235 mm), damit seine Odometrie abdriftet
                     wie die eines echten, zum Üben von Roboter &gt; Odometrie kalibrieren
  --help, --version

Ohne Verbindungsoption verbindet sich das Dashboard wieder mit den zuletzt
verwendeten Robotern, beim ersten Start mit dem virtuellen Roboter; mit einer
hält es nur diesen Roboter (oder diese virtuellen Roboter) und behält die
gespeicherte Liste für das nächste Mal. Umschalt+Esc hält jeden Roboter an.
Ohne --lang verwendet es die im Menü „Ansicht“ gewählte Sprache oder die des
Systems.
</translation>
    </message>
    <message>
        <source>--foxglove: %1</source>
        <translation>--foxglove: %1</translation>
    </message>
    <message>
        <source>
  --battery-fade PCT[,PCT...], --battery-resistance MOHM[,MOHM...]
                     with --sim: aged packs, one figure per robot (the last for
                     the rest): the share of its 3000 mAh lost (0 to 90) and its
                     internal resistance (50 to 5000 mΩ; a new pack 250)
</source>
        <translation>
  --battery-fade PROZ[,PROZ...], --battery-resistance MOHM[,MOHM...]
                     mit --sim: gealterte Akkus, ein Wert pro Roboter (der letzte für
                     die übrigen): der verlorene Anteil seiner 3000 mAh (0 bis 90) und
                     sein Innenwiderstand (50 bis 5000 mΩ; ein neuer Akku 250)
</translation>
    </message>
    <message>
        <source>--battery-fade: &apos;%1&apos; is not a share from 0 to 90 %</source>
        <translation>--battery-fade: „%1“ ist kein Anteil von 0 bis 90 %</translation>
    </message>
    <message>
        <source>--battery-resistance: &apos;%1&apos; is not a resistance from 50 to 5000 mΩ</source>
        <translation>--battery-resistance: „%1“ ist kein Widerstand von 50 bis 5000 mΩ</translation>
    </message>
    <message>
        <source>--battery-fade and --battery-resistance go with --sim</source>
        <translation>--battery-fade und --battery-resistance gehören zu --sim</translation>
    </message>
</context>
<context>
    <name>Demos</name>
    <message>
        <source>Abort demo</source>
        <translation>Demo abbrechen</translation>
    </message>
    <message>
        <source>Cover</source>
        <translation>Flächenabdeckung</translation>
    </message>
    <message>
        <source>Cover and Dock</source>
        <translation>Flächenabdeckung und Andocken</translation>
    </message>
    <message>
        <source>Spot Cover</source>
        <translation>Spot-Abdeckung</translation>
    </message>
    <message>
        <source>Mouse</source>
        <translation>Maus</translation>
    </message>
    <message>
        <source>Drive Figure Eight</source>
        <translation>Acht fahren</translation>
    </message>
    <message>
        <source>Wimp</source>
        <translation>Angsthase</translation>
    </message>
    <message>
        <source>Home</source>
        <translation>Heimkehr</translation>
    </message>
    <message>
        <source>Tag</source>
        <translation>Fangen</translation>
    </message>
    <message>
        <source>Pachelbel</source>
        <translation>Pachelbel</translation>
    </message>
    <message>
        <source>Banjo</source>
        <translation>Banjo</translation>
    </message>
</context>
<context>
    <name>DockLayout</name>
    <message>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <source>&amp;Reset layout</source>
        <translation>Layout &amp;zurücksetzen</translation>
    </message>
    <message>
        <source>&amp;Next pane</source>
        <translation>&amp;Nächster Bereich</translation>
    </message>
    <message>
        <source>&amp;Previous pane</source>
        <translation>&amp;Vorheriger Bereich</translation>
    </message>
</context>
<context>
    <name>DoctorDetails</name>
    <message>
        <source>Details…</source>
        <translation>Details …</translation>
    </message>
    <message>
        <source>Connection check details</source>
        <translation>Details der Verbindungsprüfung</translation>
    </message>
    <message>
        <source>Checking the connection…</source>
        <translation>Verbindung wird geprüft …</translation>
    </message>
    <message>
        <source>Connection check</source>
        <translation>Verbindungsprüfung</translation>
    </message>
    <message>
        <source>What was tried</source>
        <translation>Was versucht wurde</translation>
    </message>
    <message>
        <source>What was tried:</source>
        <translation>Was versucht wurde:</translation>
    </message>
    <message>
        <source>What to do next:</source>
        <translation>Was als Nächstes zu tun ist:</translation>
    </message>
</context>
<context>
    <name>DrivePad</name>
    <message>
        <source>%1 mm/s</source>
        <translation>%1 mm/s</translation>
    </message>
    <message>
        <source>Drive (137): speed and radius</source>
        <translation>Drive (137): Geschwindigkeit und Radius</translation>
    </message>
    <message>
        <source>Drive Direct (145): each wheel</source>
        <translation>Drive Direct (145): jedes Rad einzeln</translation>
    </message>
    <message>
        <source>Drive PWM (146): each wheel, raw power</source>
        <translation>Drive PWM (146): jedes Rad, Rohleistung</translation>
    </message>
    <message>
        <source>Speed limit</source>
        <translation>Tempolimit</translation>
    </message>
    <message>
        <source>Passive mode: enter Safe to drive</source>
        <translation>Modus Passive: zum Fahren Safe aktivieren</translation>
    </message>
    <message>
        <source>Enter Safe</source>
        <translation>Safe aktivieren</translation>
    </message>
    <message>
        <source>Drive pad</source>
        <translation>Fahrsteuerung</translation>
    </message>
    <message>
        <source>Drive Direct (145) is not available on the %1</source>
        <translation>Drive Direct (145) ist beim %1 nicht verfügbar</translation>
    </message>
    <message>
        <source>Drive PWM (146) is not available on the %1</source>
        <translation>Drive PWM (146) ist beim %1 nicht verfügbar</translation>
    </message>
    <message>
        <source>Drive (137) is not available on the %1</source>
        <translation>Drive (137) ist beim %1 nicht verfügbar</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Angehalten</translation>
    </message>
    <message>
        <source>Drive Direct: right %1, left %2 mm/s</source>
        <translation>Drive Direct: rechts %1, links %2 mm/s</translation>
    </message>
    <message>
        <source>Drive PWM: right %1, left %2</source>
        <translation>Drive PWM: rechts %1, links %2</translation>
    </message>
    <message>
        <source>straight</source>
        <translation>geradeaus</translation>
    </message>
    <message>
        <source>turn in place, clockwise</source>
        <translation>auf der Stelle drehen, im Uhrzeigersinn</translation>
    </message>
    <message>
        <source>turn in place, anticlockwise</source>
        <translation>auf der Stelle drehen, gegen den Uhrzeigersinn</translation>
    </message>
    <message>
        <source>radius %1 mm</source>
        <translation>Radius %1 mm</translation>
    </message>
    <message>
        <source>Drive %1 mm/s, %2</source>
        <translation>Drive %1 mm/s, %2</translation>
    </message>
    <message>
        <source>Right wheel %1 mm/s, left wheel %2 mm/s</source>
        <translation>Rechtes Rad %1 mm/s, linkes Rad %2 mm/s</translation>
    </message>
    <message>
        <source>Right wheel power %1, left wheel power %2</source>
        <translation>Leistung rechtes Rad %1, linkes Rad %2</translation>
    </message>
    <message>
        <source>Turning in place clockwise, %1 mm/s</source>
        <translation>Dreht auf der Stelle im Uhrzeigersinn, %1 mm/s</translation>
    </message>
    <message>
        <source>Turning in place anticlockwise, %1 mm/s</source>
        <translation>Dreht auf der Stelle gegen den Uhrzeigersinn, %1 mm/s</translation>
    </message>
    <message>
        <source>Forward %1 mm/s</source>
        <translation>Vorwärts %1 mm/s</translation>
    </message>
    <message>
        <source>Backward %1 mm/s</source>
        <translation>Rückwärts %1 mm/s</translation>
    </message>
    <message>
        <source>%1, straight</source>
        <translation>%1, geradeaus</translation>
    </message>
    <message>
        <source>%1, turning left (radius %2 mm)</source>
        <translation>%1, Linkskurve (Radius %2 mm)</translation>
    </message>
    <message>
        <source>%1, turning right (radius %2 mm)</source>
        <translation>%1, Rechtskurve (Radius %2 mm)</translation>
    </message>
</context>
<context>
    <name>FirmwareCorrections</name>
    <message>
        <source>This robot&apos;s firmware (before 3.3.0) reports the distance wrongly: do not trust it. The map uses the wheel encoders instead.</source>
        <translation>Die Firmware dieses Roboters (vor 3.3.0) meldet die Strecke falsch: Verlassen Sie sich nicht darauf. Die Karte nutzt stattdessen die Radencoder.</translation>
    </message>
    <message>
        <source>This robot&apos;s firmware (before 3.3.0) reports the requested radius wrongly: do not trust it.</source>
        <translation>Die Firmware dieses Roboters (vor 3.3.0) meldet den angeforderten Radius falsch: Verlassen Sie sich nicht darauf.</translation>
    </message>
</context>
<context>
    <name>FirmwareReading</name>
    <message>
        <source>Read firmware version</source>
        <translation>Firmware-Version lesen</translation>
    </message>
    <message>
        <source>Read &amp;firmware version…</source>
        <translation>&amp;Firmware-Version lesen…</translation>
    </message>
    <message>
        <source>Reset the selected robot to read its firmware version, and so what it reports wrongly</source>
        <translation>Den ausgewählten Roboter zurücksetzen, um seine Firmware-Version zu lesen und damit, was er falsch meldet</translation>
    </message>
    <message>
        <source>The firmware version is printed only when the robot starts up, so %1 will be reset (Reset, opcode 7): it stops, leaves its mode and reboots as if its battery had been taken out. Enter Safe again afterwards if you were driving it.

Reset %1 now?</source>
        <translation>Die Firmware-Version wird nur beim Start des Roboters ausgegeben, daher wird %1 zurückgesetzt (Reset, Opcode 7): Er hält an, verlässt seinen Modus und startet neu, als wäre der Akku herausgenommen worden. Aktivieren Sie danach wieder Safe, wenn Sie ihn gefahren haben.

%1 jetzt zurücksetzen?</translation>
    </message>
    <message>
        <source>%1 runs %2 (version %3).

%4

It printed: %5</source>
        <translation>%1 läuft mit %2 (Version %3).

%4

Er hat ausgegeben: %5</translation>
    </message>
    <message>
        <source>Firmware version</source>
        <translation>Firmware-Version</translation>
    </message>
</context>
<context>
    <name>FleetConsole</name>
    <message>
        <source>%1 · robots: %2 · speaking as %3</source>
        <translation>%1 · Roboter: %2 · spricht als %3</translation>
    </message>
    <message>
        <source>%1 · connecting…</source>
        <translation>%1 · wird verbunden…</translation>
    </message>
    <message>
        <source>%1 · not connected: %2</source>
        <translation>%1 · nicht verbunden: %2</translation>
    </message>
    <message>
        <source>this window</source>
        <translation>dieses Fenster</translation>
    </message>
    <message>
        <source>Stopped the robot at %1</source>
        <translation>Roboter um %1 angehalten</translation>
    </message>
    <message>
        <source>Stopped all %1 robots at %2</source>
        <translation>Alle %1 Roboter um %2 angehalten</translation>
    </message>
    <message>
        <source>%1 · connection lost at %2, trying again…</source>
        <translation>%1 · Verbindung um %2 verloren, neuer Versuch…</translation>
    </message>
</context>
<context>
    <name>FleetDirectory</name>
    <message>
        <source>%1: %2 is not JSON: %3</source>
        <translation>%1: %2 ist kein JSON: %3</translation>
    </message>
    <message>
        <source>%1: %2 is not a JSON object</source>
        <translation>%1: %2 ist kein JSON-Objekt</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1: telemetry: %2</source>
        <translation>%1: Telemetrie: %2</translation>
    </message>
    <message>
        <source>%1: stats: %2</source>
        <translation>%1: Statistik: %2</translation>
    </message>
</context>
<context>
    <name>FleetTile</name>
    <message>
        <source>ONLINE</source>
        <translation>ONLINE</translation>
    </message>
    <message>
        <source>OFFLINE</source>
        <translation>OFFLINE</translation>
    </message>
    <message>
        <source>mode not known</source>
        <translation>Modus unbekannt</translation>
    </message>
    <message>
        <source>BUMP both</source>
        <translation>STOSS beide</translation>
    </message>
    <message>
        <source>BUMP left</source>
        <translation>STOSS links</translation>
    </message>
    <message>
        <source>BUMP right</source>
        <translation>STOSS rechts</translation>
    </message>
    <message>
        <source>CLIFF ×%1</source>
        <translation>ABGRUND ×%1</translation>
    </message>
    <message>
        <source>WHEEL DROP</source>
        <translation>RAD HÄNGT</translation>
    </message>
    <message>
        <source>no bump, no cliff</source>
        <translation>kein Stoß, kein Abgrund</translation>
    </message>
    <message>
        <source>link not known</source>
        <translation>Verbindung unbekannt</translation>
    </message>
    <message>
        <source>link %1</source>
        <translation>Verbindung %1</translation>
    </message>
    <message>
        <source>%1 · %2/s</source>
        <translation>%1 · %2/s</translation>
    </message>
    <message>
        <source>nobody in control</source>
        <translation>niemand steuert</translation>
    </message>
    <message>
        <source>driven by %1</source>
        <translation>gesteuert von %1</translation>
    </message>
    <message>
        <source>Robot %1, %2</source>
        <translation>Roboter %1, %2</translation>
    </message>
    <message>
        <source>%1
Click to select this robot: every dock shows it</source>
        <translation>%1
Klicken wählt diesen Roboter: jedes Dock zeigt ihn</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>NO BROKER</source>
        <translation>KEIN BROKER</translation>
    </message>
    <message>
        <source>battery %1 %</source>
        <translation>Akku %1 %</translation>
    </message>
    <message>
        <source>%1 · %2</source>
        <translation>%1 · %2</translation>
    </message>
    <message>
        <source>broker unreachable</source>
        <translation>Broker nicht erreichbar</translation>
    </message>
    <message>
        <source>%1&apos;s program %2</source>
        <translation>Programm %2 von %1</translation>
    </message>
    <message>
        <source>MAY STILL BE MOVING</source>
        <translation>FÄHRT EVTL. NOCH</translation>
    </message>
    <message>
        <source>pack %1, %2 mAh</source>
        <translation>Akku %1, %2 mAh</translation>
    </message>
    <message>
        <source>pack %1</source>
        <translation>Akku %1</translation>
    </message>
    <message>
        <source>%1 % · %2</source>
        <translation>%1 % · %2</translation>
    </message>
    <message>
        <source>pick it up, switch it off</source>
        <translation>hochheben, ausschalten</translation>
    </message>
    <message>
        <source>bridge offline since %1</source>
        <translation>Bridge offline seit %1</translation>
    </message>
    <message>
        <source>bridge offline</source>
        <translation>Bridge offline</translation>
    </message>
    <message>
        <source>robot not answering</source>
        <translation>Roboter antwortet nicht</translation>
    </message>
    <message>
        <source>robot silent (link stale)</source>
        <translation>Roboter still (veraltet)</translation>
    </message>
    <message>
        <source>%1 cut off</source>
        <translation>%1 getrennt</translation>
    </message>
    <message>
        <source>%1&apos;s program cut off</source>
        <translation>Programm von %1 abgebrochen</translation>
    </message>
    <message>
        <source>, cutting off %1</source>
        <translation>, wodurch %1 getrennt wurde</translation>
    </message>
    <message>
        <source>, cutting off %1&apos;s program %2</source>
        <translation>, wodurch das Programm %2 von %1 abbrach</translation>
    </message>
    <message>
        <source>%1&apos;s bridge went offline at %2 while the robot was driving%3. A real robot keeps its last drive when its bridge dies: pick it up and hold its power button to switch it off, then restart the bridge on the computer beside it.</source>
        <translation>Die Bridge von %1 ging um %2 offline, während der Roboter fuhr%3. Ein echter Roboter behält seinen letzten Fahrbefehl, wenn seine Bridge ausfällt: Heben Sie ihn hoch und halten Sie seine Ein/Aus-Taste gedrückt, um ihn auszuschalten, und starten Sie dann die Bridge auf dem Computer neben ihm neu.</translation>
    </message>
    <message>
        <source>%1&apos;s bridge went offline at %2%3 (the broker is fine): check the bridge on the computer beside the robot, and restart it.</source>
        <translation>Die Bridge von %1 ging um %2 offline%3 (der Broker läuft): Prüfen Sie die Bridge auf dem Computer neben dem Roboter, und starten Sie sie neu.</translation>
    </message>
    <message>
        <source>%1
%2
Click to select this robot: every dock shows it</source>
        <translation>%1
%2
Klicken wählt diesen Roboter: jedes Dock zeigt ihn</translation>
    </message>
</context>
<context>
    <name>FleetView</name>
    <message>
        <source>Fleet view</source>
        <translation>Flottenansicht</translation>
    </message>
    <message>
        <source>Connect to broker…</source>
        <translation>Mit Broker verbinden…</translation>
    </message>
    <message>
        <source>Not connected to a broker</source>
        <translation>Mit keinem Broker verbunden</translation>
    </message>
    <message>
        <source>Connect to a broker to see every robot whose bridge publishes there.</source>
        <translation>Verbinden Sie sich mit einem Broker, um jeden Roboter zu sehen, dessen Bridge dort veröffentlicht.</translation>
    </message>
    <message>
        <source>No robot on this broker yet. Each appears as its bridge starts.</source>
        <translation>Noch kein Roboter auf diesem Broker. Jeder erscheint, sobald seine Bridge startet.</translation>
    </message>
    <message>
        <source>Reconnect…</source>
        <translation>Neu verbinden…</translation>
    </message>
    <message>
        <source>Another broker…</source>
        <translation>Anderer Broker…</translation>
    </message>
    <message>
        <source>By name</source>
        <translation>Nach Name</translation>
    </message>
    <message>
        <source>By pack health</source>
        <translation>Nach Akkuzustand</translation>
    </message>
    <message>
        <source>The order of the tiles: by name, or by the health of each robot&apos;s battery pack, the one to replace first.</source>
        <translation>Die Reihenfolge der Kacheln: nach Name oder nach dem Zustand des Akkus jedes Roboters, der zuerst zu ersetzende vorn.</translation>
    </message>
</context>
<context>
    <name>GamepadInput</name>
    <message>
        <source>Back</source>
        <translation>Back</translation>
    </message>
    <message>
        <source>Guide</source>
        <translation>Guide</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>Left stick press</source>
        <translation>Linker Stick gedrückt</translation>
    </message>
    <message>
        <source>Right stick press</source>
        <translation>Rechter Stick gedrückt</translation>
    </message>
    <message>
        <source>D-pad up</source>
        <translation>Steuerkreuz oben</translation>
    </message>
    <message>
        <source>D-pad down</source>
        <translation>Steuerkreuz unten</translation>
    </message>
    <message>
        <source>D-pad left</source>
        <translation>Steuerkreuz links</translation>
    </message>
    <message>
        <source>D-pad right</source>
        <translation>Steuerkreuz rechts</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>button %1</source>
        <translation>Taste %1</translation>
    </message>
    <message>
        <source>Passive (128)</source>
        <translation>Passive (128)</translation>
    </message>
    <message>
        <source>Safe (131)</source>
        <translation>Safe (131)</translation>
    </message>
    <message>
        <source>Full (132)</source>
        <translation>Full (132)</translation>
    </message>
    <message>
        <source>command %1</source>
        <translation>Befehl %1</translation>
    </message>
    <message>
        <source>Gamepad</source>
        <translation>Gamepad</translation>
    </message>
</context>
<context>
    <name>GamepadPanel</name>
    <message>
        <source>Would send:</source>
        <translation>Würde senden:</translation>
    </message>
    <message>
        <source>Left stick</source>
        <translation>Linker Stick</translation>
    </message>
    <message>
        <source>Drive Direct: right %1 mm/s, left %2 mm/s</source>
        <translation>Drive Direct: rechts %1 mm/s, links %2 mm/s</translation>
    </message>
    <message>
        <source>Drive PWM: right %1, left %2</source>
        <translation>Drive PWM: rechts %1, links %2</translation>
    </message>
    <message>
        <source>Stop: Drive 0 mm/s</source>
        <translation>Stopp: Drive 0 mm/s</translation>
    </message>
    <message>
        <source>Forward: Drive %1 mm/s, straight</source>
        <translation>Vorwärts: Drive %1 mm/s, geradeaus</translation>
    </message>
    <message>
        <source>Reverse: Drive %1 mm/s, straight</source>
        <translation>Rückwärts: Drive %1 mm/s, geradeaus</translation>
    </message>
    <message>
        <source>Spin clockwise: Drive %1 mm/s, radius -1</source>
        <translation>Drehen im Uhrzeigersinn: Drive %1 mm/s, Radius -1</translation>
    </message>
    <message>
        <source>Spin counter-clockwise: Drive %1 mm/s, radius 1</source>
        <translation>Drehen gegen den Uhrzeigersinn: Drive %1 mm/s, Radius 1</translation>
    </message>
    <message>
        <source>Forward, arcing right</source>
        <translation>Vorwärts, Bogen nach rechts</translation>
    </message>
    <message>
        <source>Forward, arcing left</source>
        <translation>Vorwärts, Bogen nach links</translation>
    </message>
    <message>
        <source>Reverse, arcing right</source>
        <translation>Rückwärts, Bogen nach rechts</translation>
    </message>
    <message>
        <source>Reverse, arcing left</source>
        <translation>Rückwärts, Bogen nach links</translation>
    </message>
    <message>
        <source>%1: Drive %2 mm/s, radius %3 mm</source>
        <translation>%1: Drive %2 mm/s, Radius %3 mm</translation>
    </message>
    <message>
        <source>Gamepads unavailable: %1</source>
        <translation>Gamepads nicht verfügbar: %1</translation>
    </message>
    <message>
        <source>No gamepad connected — plug one in to drive with it</source>
        <translation>Kein Gamepad verbunden – zum Fahren eines anschließen</translation>
    </message>
    <message>
        <source>Dead-man (%1) held: driving</source>
        <translation>Totmannschalter (%1) gehalten: Fahrt</translation>
    </message>
    <message>
        <source>Dead-man (%1) released: hold it to drive</source>
        <translation>Totmannschalter (%1) losgelassen: zum Fahren gedrückt halten</translation>
    </message>
    <message>
        <source>%1% right, %2% forward</source>
        <translation>%1% rechts, %2% vorwärts</translation>
    </message>
    <message>
        <source>Speed limit %1 mm/s · deadband %2% · expo %3</source>
        <translation>Tempolimit %1 mm/s · Totzone %2% · Expo %3</translation>
    </message>
    <message>
        <source>Hold %1 to drive</source>
        <translation>Zum Fahren %1 gedrückt halten</translation>
    </message>
    <message>
        <source>%1: Stop All</source>
        <translation>%1: Alles stoppen</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>InfraredName</name>
    <message>
        <source>Arc Forward Left</source>
        <translation>Bogen vorwärts links</translation>
    </message>
    <message>
        <source>Arc Forward Right</source>
        <translation>Bogen vorwärts rechts</translation>
    </message>
    <message>
        <source>Arc Left</source>
        <translation>Bogen links</translation>
    </message>
    <message>
        <source>Arc Right</source>
        <translation>Bogen rechts</translation>
    </message>
    <message>
        <source>Dock (reserved)</source>
        <translation>Dock (reserviert)</translation>
    </message>
    <message>
        <source>Download</source>
        <translation>Download</translation>
    </message>
    <message>
        <source>Drive Stop</source>
        <translation>Fahrt stoppen</translation>
    </message>
    <message>
        <source>Fence</source>
        <translation>Zaun</translation>
    </message>
    <message>
        <source>Force Field</source>
        <translation>Kraftfeld</translation>
    </message>
    <message>
        <source>Forward</source>
        <translation>Vorwärts</translation>
    </message>
    <message>
        <source>Green Buoy</source>
        <translation>Grüne Boje</translation>
    </message>
    <message>
        <source>Large / Clean</source>
        <translation>Groß / Clean</translation>
    </message>
    <message>
        <source>Left</source>
        <translation>Links</translation>
    </message>
    <message>
        <source>Max</source>
        <translation>Max</translation>
    </message>
    <message>
        <source>Medium</source>
        <translation>Mittel</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Keins</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Power</source>
        <translation>Ein/Aus</translation>
    </message>
    <message>
        <source>Red Buoy</source>
        <translation>Rote Boje</translation>
    </message>
    <message>
        <source>Right</source>
        <translation>Rechts</translation>
    </message>
    <message>
        <source>Seek Dock</source>
        <translation>Dock suchen</translation>
    </message>
    <message>
        <source>Send All</source>
        <translation>Alle senden</translation>
    </message>
    <message>
        <source>Small</source>
        <translation>Klein</translation>
    </message>
    <message>
        <source>Spot</source>
        <translation>Spot</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>Virtual Wall</source>
        <translation>Virtuelle Wand</translation>
    </message>
    <message>
        <source> and </source>
        <translation> und </translation>
    </message>
    <message>
        <source>Lighthouse (unbound) %1</source>
        <translation>Leuchtturm (ungebunden) %1</translation>
    </message>
    <message>
        <source>Lighthouse %1 %2</source>
        <translation>Leuchtturm %1 %2</translation>
    </message>
    <message>
        <source>IR %1</source>
        <translation>IR %1</translation>
    </message>
    <message>
        <source>Red</source>
        <comment>the dock&apos;s red buoy, in a small box</comment>
        <translation>Rot</translation>
    </message>
    <message>
        <source>Green</source>
        <comment>the dock&apos;s green buoy, in a small box</comment>
        <translation>Grün</translation>
    </message>
    <message>
        <source>Field</source>
        <comment>the dock&apos;s force field, in a small box</comment>
        <translation>Feld</translation>
    </message>
</context>
<context>
    <name>LanguageMenu</name>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <source>System default</source>
        <translation>Systemstandard</translation>
    </message>
</context>
<context>
    <name>LedEditor</name>
    <message>
        <source>Live</source>
        <translation>Live</translation>
    </message>
    <message>
        <source>Send changes as you make them, at most every %1 ms</source>
        <translation>Änderungen sofort senden, höchstens alle %1 ms</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Anwenden</translation>
    </message>
    <message>
        <source>Will send:</source>
        <translation>Wird gesendet:</translation>
    </message>
    <message>
        <source>7-segment display (163, 164)</source>
        <translation>7-Segment-Anzeige (163, 164)</translation>
    </message>
    <message>
        <source>Click a segment to switch it on or off</source>
        <translation>Segment anklicken, um es ein- oder auszuschalten</translation>
    </message>
    <message>
        <source>Segment editor</source>
        <translation>Segment-Editor</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Leeren</translation>
    </message>
    <message>
        <source>Switch every segment off</source>
        <translation>Alle Segmente ausschalten</translation>
    </message>
    <message>
        <source>up to 4 characters</source>
        <translation>bis zu 4 Zeichen</translation>
    </message>
    <message>
        <source>Text for the display</source>
        <translation>Text für die Anzeige</translation>
    </message>
    <message>
        <source>The robot&apos;s approximation of the text</source>
        <translation>Der Text, wie der Roboter ihn annähernd darstellt</translation>
    </message>
    <message>
        <source>What the robot shows</source>
        <translation>Was der Roboter anzeigt</translation>
    </message>
    <message>
        <source>&lt;b&gt;Segments&lt;/b&gt; (Digit LEDs Raw, 163): click to switch</source>
        <translation>&lt;b&gt;Segmente&lt;/b&gt; (Digit LEDs Raw, 163): zum Umschalten klicken</translation>
    </message>
    <message>
        <source>&lt;b&gt;Text&lt;/b&gt; (Digit LEDs ASCII, 164)</source>
        <translation>&lt;b&gt;Text&lt;/b&gt; (Digit LEDs ASCII, 164)</translation>
    </message>
    <message>
        <source>What the robot shows:</source>
        <translation>Was der Roboter anzeigt:</translation>
    </message>
    <message>
        <source>LEDs (139)</source>
        <translation>LEDs (139)</translation>
    </message>
    <message>
        <source>Debris</source>
        <translation>Schmutz</translation>
    </message>
    <message>
        <source>Spot</source>
        <translation>Spot</translation>
    </message>
    <message>
        <source>Dock</source>
        <translation>Dock</translation>
    </message>
    <message>
        <source>Check Robot</source>
        <translation>Roboter prüfen</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Play</translation>
    </message>
    <message>
        <source>Advance</source>
        <translation>Advance</translation>
    </message>
    <message>
        <source>0 green … 255 red</source>
        <translation>0 grün … 255 rot</translation>
    </message>
    <message>
        <source>Power colour</source>
        <translation>Power-Farbe</translation>
    </message>
    <message>
        <source>Intensity</source>
        <translation>Helligkeit</translation>
    </message>
    <message>
        <source>The power LED as set</source>
        <translation>Die Power-LED wie eingestellt</translation>
    </message>
    <message>
        <source>Power LED</source>
        <translation>Power-LED</translation>
    </message>
    <message>
        <source>green</source>
        <translation>grün</translation>
    </message>
    <message>
        <source>red</source>
        <translation>rot</translation>
    </message>
    <message>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <source>full</source>
        <translation>voll</translation>
    </message>
    <message>
        <source>Scheduling LEDs (162)</source>
        <translation>Zeitplan-LEDs (162)</translation>
    </message>
    <message>
        <source>Sun</source>
        <translation>So</translation>
    </message>
    <message>
        <source>Mon</source>
        <translation>Mo</translation>
    </message>
    <message>
        <source>Tue</source>
        <translation>Di</translation>
    </message>
    <message>
        <source>Wed</source>
        <translation>Mi</translation>
    </message>
    <message>
        <source>Thu</source>
        <translation>Do</translation>
    </message>
    <message>
        <source>Fri</source>
        <translation>Fr</translation>
    </message>
    <message>
        <source>Sat</source>
        <translation>Sa</translation>
    </message>
    <message>
        <source>Schedule</source>
        <translation>Zeitplan</translation>
    </message>
    <message>
        <source>Clock</source>
        <translation>Uhr</translation>
    </message>
    <message>
        <source>AM</source>
        <translation>AM</translation>
    </message>
    <message>
        <source>PM</source>
        <translation>PM</translation>
    </message>
    <message>
        <source>Colon</source>
        <translation>Doppelpunkt</translation>
    </message>
    <message>
        <source>The %1 has no 7-segment display: Digit LEDs Raw (163) and Digit LEDs ASCII (164) are Roomba 500 / Create 2 only.</source>
        <translation>Der %1 hat keine 7-Segment-Anzeige: Digit LEDs Raw (163) und Digit LEDs ASCII (164) gibt es nur bei Roomba 500 / Create 2.</translation>
    </message>
    <message>
        <source>⚠ Digit LEDs Raw (163) does not work in current Create 2 and Roomba 500/600 firmware. It is sent anyway; use Text (164) to be sure.</source>
        <translation>⚠ Digit LEDs Raw (163) funktioniert mit der aktuellen Firmware von Create 2 und Roomba 500/600 nicht. Es wird trotzdem gesendet; verwenden Sie zur Sicherheit Text (164).</translation>
    </message>
    <message>
        <source>%1.</source>
        <translation>%1.</translation>
    </message>
    <message>
        <source>Not sent: %1 outside ASCII 32..126. Use letters, digits and punctuation.</source>
        <translation>Nicht gesendet: %1 außerhalb von ASCII 32..126. Verwenden Sie Buchstaben, Ziffern und Satzzeichen.</translation>
    </message>
    <message>
        <source>%1 shows blank: the robot has no shape for it.</source>
        <translation>%1 bleibt leer: Der Roboter hat dafür keine Form.</translation>
    </message>
    <message>
        <source>%1 show blank: the robot has no shape for them.</source>
        <translation>%1 bleiben leer: Der Roboter hat dafür keine Form.</translation>
    </message>
    <message>
        <source>Colour %1 of 255 (green to red), intensity %2 of 255</source>
        <translation>Farbe %1 von 255 (grün bis rot), Helligkeit %2 von 255</translation>
    </message>
    <message>
        <source>nothing (no changes since the last send)</source>
        <translation>nichts (keine Änderungen seit dem letzten Senden)</translation>
    </message>
    <message>
        <source>Live mode sends changes as you make them</source>
        <translation>Im Live-Modus werden Änderungen sofort gesendet</translation>
    </message>
    <message>
        <source>Send the changes shown under &quot;Will send&quot;</source>
        <translation>Die unter „Wird gesendet“ angezeigten Änderungen senden</translation>
    </message>
    <message>
        <source>Dirt Detect</source>
        <translation>Schmutzerkennung</translation>
    </message>
    <message>
        <source>Max</source>
        <translation>Max</translation>
    </message>
    <message>
        <source>Clean</source>
        <translation>Clean</translation>
    </message>
</context>
<context>
    <name>Lesson</name>
    <message>
        <source>Battery and current while driving</source>
        <translation>Akku und Strom beim Fahren</translation>
    </message>
    <message>
        <source>Where the energy goes: the battery&apos;s voltage, charge and current, standing and driving.</source>
        <translation>Wohin die Energie geht: Spannung, Ladung und Strom des Akkus, im Stand und beim Fahren.</translation>
    </message>
    <message>
        <source>The battery reports its voltage, its charge and the current flowing in or out of it. A negative current flows out of the battery. Keep the robot still, off the dock: the current stays small, above -400 mA, for two seconds.</source>
        <translation>Der Akku meldet seine Spannung, seine Ladung und den Strom, der hinein- oder herausfließt. Ein negativer Strom fließt aus dem Akku heraus. Lassen Sie den Roboter still stehen, nicht auf dem Dock: Der Strom bleibt zwei Sekunden lang klein, über -400 mA.</translation>
    </message>
    <message>
        <source>Now drive. The wheel motors draw current from the battery, so the current goes further below zero. Keep driving until the current stays under -400 mA for two seconds.</source>
        <translation>Jetzt fahren. Die Radmotoren ziehen Strom aus dem Akku, deshalb sinkt der Strom weiter unter null. Fahren Sie, bis der Strom zwei Sekunden lang unter -400 mA bleibt.</translation>
    </message>
    <message>
        <source>Stop the robot. The motors stop drawing and the current comes back to what the robot needs to stand still: above -400 mA for two seconds. The voltage rises a little too.</source>
        <translation>Halten Sie den Roboter an. Die Motoren ziehen keinen Strom mehr, und der Strom geht auf das zurück, was der Roboter im Stand braucht: zwei Sekunden lang über -400 mA. Auch die Spannung steigt ein wenig.</translation>
    </message>
    <message>
        <source>Bumpers and wheel drops</source>
        <translation>Stoßfänger und Radabsenkung</translation>
    </message>
    <message>
        <source>The switches that tell the robot it has hit something or lost the floor.</source>
        <translation>Die Schalter, die dem Roboter sagen, dass er angestoßen ist oder den Boden verloren hat.</translation>
    </message>
    <message>
        <source>Put the robot back down, away from any wall. Every switch opens again: packet 7 reads 0 for a whole second.</source>
        <translation>Setzen Sie den Roboter wieder ab, weg von jeder Wand. Alle Schalter öffnen wieder: Paket 7 zeigt eine ganze Sekunde lang 0.</translation>
    </message>
    <message>
        <source>Cliff sensors</source>
        <translation>Abgrundsensoren</translation>
    </message>
    <message>
        <source>Four infrared eyes under the bumper that keep the robot from falling down the stairs.</source>
        <translation>Vier Infrarotaugen unter dem Stoßfänger, die den Roboter davor bewahren, die Treppe hinunterzufallen.</translation>
    </message>
    <message>
        <source>Under the front of the robot, four cliff sensors shine infrared light at the floor and measure how much comes back. On the floor each signal is high. Keep the robot on the floor and watch the front signals stay above 1000 for two seconds.</source>
        <translation>Vorn unter dem Roboter leuchten vier Abgrundsensoren mit Infrarotlicht auf den Boden und messen, wie viel zurückkommt. Auf dem Boden ist jedes Signal hoch. Lassen Sie den Roboter auf dem Boden und sehen Sie zu, wie die vorderen Signale zwei Sekunden lang über 1000 bleiben.</translation>
    </message>
    <message>
        <source>Encoders, distance and angle</source>
        <translation>Encoder, Strecke und Winkel</translation>
    </message>
    <message>
        <source>How the robot knows how far it drove and which way it points, and how wrong it gets.</source>
        <translation>Wie der Roboter weiß, wie weit er gefahren ist und wohin er zeigt, und wie sehr er sich dabei irrt.</translation>
    </message>
    <message>
        <source>Each drive wheel turns an encoder that counts its steps. The dashboard adds up the steps of both wheels to work out how far the robot went: odometry. Drive straight ahead for one metre.</source>
        <translation>Jedes Antriebsrad dreht einen Encoder, der seine Schritte zählt. Das Dashboard zählt die Schritte beider Räder zusammen und berechnet daraus, wie weit der Roboter gefahren ist: Odometrie. Fahren Sie einen Meter geradeaus.</translation>
    </message>
    <message>
        <source>Now turn on the spot, a quarter turn: 90 degrees. When one wheel goes forward and the other back, the difference between them is the angle. On the virtual robot, compare odometry with the way the robot truly points.</source>
        <translation>Drehen Sie jetzt auf der Stelle, eine Vierteldrehung: 90 Grad. Läuft ein Rad vorwärts und das andere rückwärts, ergibt ihr Unterschied den Winkel. Vergleichen Sie beim virtuellen Roboter die Odometrie mit der Richtung, in die der Roboter wirklich zeigt.</translation>
    </message>
    <message>
        <source>Turn a whole circle, 360 degrees. Small errors add up: watch how far the odometry and the true turn drift apart.</source>
        <translation>Drehen Sie eine ganze Runde, 360 Grad. Kleine Fehler summieren sich: Sehen Sie zu, wie weit Odometrie und wahre Drehung auseinanderlaufen.</translation>
    </message>
    <message>
        <source>IR from the dock and the virtual wall</source>
        <translation>IR vom Dock und von der virtuellen Wand</translation>
    </message>
    <message>
        <source>Invisible beams that lead the robot home and keep it out.</source>
        <translation>Unsichtbare Strahlen, die den Roboter nach Hause führen und ihn fernhalten.</translation>
    </message>
    <message>
        <source>Light bumpers and wall following</source>
        <translation>Lichtstoßfänger und Wandfolgen</translation>
    </message>
    <message>
        <source>Seeing a wall before touching it, and keeping beside it.</source>
        <translation>Eine Wand sehen, bevor man sie berührt, und neben ihr bleiben.</translation>
    </message>
    <message>
        <source>Each light bumper also has an on/off flag in packet 45, set when its signal is strong. Come close enough that the centre left and centre right flags are on together.</source>
        <translation>Jeder Lichtstoßfänger hat auch ein Ein/Aus-Flag in Paket 45, das bei starkem Signal gesetzt wird. Kommen Sie so nah heran, dass die Flags Mitte links und Mitte rechts zugleich an sind.</translation>
    </message>
    <message>
        <source>The bumper is one piece, but behind it sit two switches, one on the left and one on the right. Press the left half of the bumper gently. On the virtual robot, put its left front by a wall with the button below, then drive forward (Up arrow) until it touches.</source>
        <translation>Der Stoßfänger ist ein Teil, aber dahinter sitzen zwei Schalter, einer links und einer rechts. Drücken Sie vorsichtig auf die linke Hälfte des Stoßfängers. Beim virtuellen Roboter stellen Sie ihn mit dem Knopf unten mit der linken Vorderseite an eine Wand und fahren vorwärts (Pfeil nach oben), bis er sie berührt.</translation>
    </message>
    <message>
        <source>Now press the right half of the bumper. On the virtual robot, put its right front by the wall with the button below and drive forward. Watch packet 7: the left bumper is one bit, the right bumper another.</source>
        <translation>Drücken Sie jetzt auf die rechte Hälfte des Stoßfängers. Beim virtuellen Roboter stellen Sie ihn mit dem Knopf unten mit der rechten Vorderseite an die Wand und fahren vorwärts. Achten Sie auf Paket 7: Der linke Stoßfänger ist ein Bit, der rechte ein anderes.</translation>
    </message>
    <message>
        <source>Press the middle of the bumper, or drive straight into a wall: both switches close at once, and the robot knows the obstacle is straight ahead. On the virtual robot, face the wall with the button below, then drive forward.</source>
        <translation>Drücken Sie auf die Mitte des Stoßfängers oder fahren Sie gerade gegen eine Wand: Beide Schalter schließen zugleich, und der Roboter weiß, dass das Hindernis genau vor ihm ist. Beim virtuellen Roboter richten Sie ihn mit dem Knopf unten auf die Wand aus und fahren dann vorwärts.</translation>
    </message>
    <message>
        <source>Lift the robot a little off the floor. Each drive wheel drops down on its spring and closes a switch. Lift it until both wheels hang. In Safe mode the robot drops to Passive when its wheels drop: that is expected here. On the virtual robot, lift it with the button below.</source>
        <translation>Heben Sie den Roboter ein wenig vom Boden. Jedes Antriebsrad senkt sich an seiner Feder ab und schließt einen Schalter. Heben Sie ihn, bis beide Räder hängen. Im Safe-Modus fällt der Roboter in Passive zurück, wenn sich seine Räder absenken: Das ist hier so gewollt. Beim virtuellen Roboter heben Sie ihn mit dem Knopf unten an.</translation>
    </message>
    <message>
        <source>Put its left front by a wall</source>
        <translation>Linke Vorderseite an eine Wand stellen</translation>
    </message>
    <message>
        <source>Put its right front by the wall</source>
        <translation>Rechte Vorderseite an die Wand stellen</translation>
    </message>
    <message>
        <source>Face the wall head on</source>
        <translation>Gerade auf die Wand ausrichten</translation>
    </message>
    <message>
        <source>Lift it off the floor</source>
        <translation>Vom Boden heben</translation>
    </message>
    <message>
        <source>Put it down in the open</source>
        <translation>Im Freien absetzen</translation>
    </message>
    <message>
        <source>Drive slowly towards the edge of a table or a step, in Safe mode, or lift the front of the robot a little. On the virtual robot, carry it to the stage edge with the button below, then drive forward (Up arrow). When a front sensor loses the floor, the robot sets its cliff flag and, in Safe mode, stops and drops to Passive. A dark rug does the same, though the floor is there: then the signals stay low but well above 0 and no wheel drops. Either way, carry the robot back onto a light floor before you drive again.</source>
        <translation>Fahren Sie im Safe-Modus langsam auf die Kante eines Tisches oder einer Stufe zu, oder heben Sie die Vorderseite des Roboters ein wenig an. Beim virtuellen Roboter tragen Sie ihn mit dem Knopf unten an die Bühnenkante und fahren dann vorwärts (Pfeil nach oben). Wenn ein vorderer Sensor den Boden verliert, setzt der Roboter sein Abgrund-Flag, hält im Safe-Modus an und fällt in Passive zurück. Ein dunkler Teppich bewirkt dasselbe, obwohl der Boden da ist: Dann bleiben die Signale niedrig, aber deutlich über 0, und kein Rad senkt sich ab. In beiden Fällen tragen Sie den Roboter auf einen hellen Boden zurück, bevor Sie wieder fahren.</translation>
    </message>
    <message>
        <source>Look at the signal behind the flag: over the edge almost no light comes back. The robot stopped, as the yellow line says; leave it in Passive for now and hold it a little further over the edge, so that a front signal stays under 500 for half a second. On the virtual robot, use the button below.</source>
        <translation>Sehen Sie sich das Signal hinter dem Flag an: Über der Kante kommt fast kein Licht zurück. Der Roboter hat angehalten, wie die gelbe Zeile sagt; lassen Sie ihn vorerst in Passive und halten Sie ihn ein wenig weiter über die Kante, sodass ein vorderes Signal eine halbe Sekunde lang unter 500 bleibt. Beim virtuellen Roboter nehmen Sie den Knopf unten.</translation>
    </message>
    <message>
        <source>Carry the robot back onto the floor, away from the edge. The flags clear and the signals rise again: both front signals above 1000 for one second. On the virtual robot, use the button below.</source>
        <translation>Tragen Sie den Roboter zurück auf den Boden, weg von der Kante. Die Flags gehen aus und die Signale steigen wieder: beide vorderen Signale eine Sekunde lang über 1000. Beim virtuellen Roboter nehmen Sie den Knopf unten.</translation>
    </message>
    <message>
        <source>Carry it to face the stage edge</source>
        <translation>Vor die Bühnenkante tragen</translation>
    </message>
    <message>
        <source>Hold it further over the edge</source>
        <translation>Weiter über die Kante halten</translation>
    </message>
    <message>
        <source>Carry it back onto the floor</source>
        <translation>Zurück auf den Boden tragen</translation>
    </message>
    <message>
        <source>The IR receiver at the front of the robot picks up infrared beams. The dock sends out two buoys, red and green, and a short force field. Place the robot a metre in front of the dock, facing it, until the receiver sees the dock. On the virtual robot, use the button below.</source>
        <translation>Der IR-Empfänger vorn am Roboter empfängt Infrarotstrahlen. Das Dock sendet zwei Bojen aus, rot und grün, und ein kurzes Kraftfeld. Stellen Sie den Roboter einen Meter vor das Dock, mit Blick darauf, bis der Empfänger das Dock sieht. Beim virtuellen Roboter nehmen Sie den Knopf unten.</translation>
    </message>
    <message>
        <source>A virtual wall sends a beam that the robot will not cross. Bring the robot into the beam of the virtual wall: the virtual wall flag, packet 13, turns on. In the virtual classroom, the virtual wall stands on the front wall; the button below carries the robot into its beam.</source>
        <translation>Eine virtuelle Wand sendet einen Strahl, den der Roboter nicht überquert. Bringen Sie den Roboter in den Strahl der virtuellen Wand: Das Flag für die virtuelle Wand, Paket 13, geht an. Im virtuellen Klassenzimmer steht die virtuelle Wand an der vorderen Wand; der Knopf unten trägt den Roboter in ihren Strahl.</translation>
    </message>
    <message>
        <source>Drive the robot onto the dock, nose first, following the buoys. When its contacts touch the dock, the home base shows up as a charging source. On the virtual robot, put it in front of the dock with the button below, then drive forward (Up arrow).</source>
        <translation>Fahren Sie den Roboter mit der Nase voran auf das Dock und folgen Sie dabei den Bojen. Berühren seine Kontakte das Dock, erscheint die Ladestation als Ladequelle. Beim virtuellen Roboter stellen Sie ihn mit dem Knopf unten vor das Dock und fahren dann vorwärts (Pfeil nach oben).</translation>
    </message>
    <message>
        <source>Put it a metre from the dock, facing it</source>
        <translation>Einen Meter vor das Dock stellen, mit Blick darauf</translation>
    </message>
    <message>
        <source>Carry it into the virtual wall&apos;s beam</source>
        <translation>In den Strahl der virtuellen Wand tragen</translation>
    </message>
    <message>
        <source>Put it in front of the dock</source>
        <translation>Vor das Dock stellen</translation>
    </message>
    <message>
        <source>Six light bumpers look out through the window of the bumper. Each one shines infrared light and measures what a wall sends back. Move the robot slowly towards a wall, facing it, until the centre left signal is above 1000. On the virtual robot, face a wall with the button below, then drive forward (Up arrow).</source>
        <translation>Sechs Lichtstoßfänger schauen durch das Fenster des Stoßfängers. Jeder leuchtet mit Infrarotlicht und misst, was eine Wand zurückwirft. Bewegen Sie den Roboter langsam auf eine Wand zu, mit Blick darauf, bis das Signal Mitte links über 1000 liegt. Beim virtuellen Roboter richten Sie ihn mit dem Knopf unten auf eine Wand aus und fahren dann vorwärts (Pfeil nach oben).</translation>
    </message>
    <message>
        <source>The wall sensor on the right side looks sideways. Turn the robot so that the wall is on its right and drive along it, a few centimetres away. Keep the wall signal above 30 for three seconds. On the virtual robot, put it beside the wall with the button below, then drive forward.</source>
        <translation>Der Wandsensor auf der rechten Seite schaut zur Seite. Drehen Sie den Roboter so, dass die Wand rechts von ihm ist, und fahren Sie ein paar Zentimeter entfernt an ihr entlang. Halten Sie das Wandsignal drei Sekunden lang über 30. Beim virtuellen Roboter stellen Sie ihn mit dem Knopf unten neben die Wand und fahren dann vorwärts.</translation>
    </message>
    <message>
        <source>Come closer to the wall, about four centimetres: the robot decides that a wall is there and sets the wall flag, packet 8. Keep it on for one second. On the virtual robot, use the button below.</source>
        <translation>Kommen Sie näher an die Wand, etwa vier Zentimeter: Der Roboter entscheidet, dass dort eine Wand ist, und setzt das Wand-Flag, Paket 8. Lassen Sie es eine Sekunde lang an. Beim virtuellen Roboter nehmen Sie den Knopf unten.</translation>
    </message>
    <message>
        <source>Face it to a wall</source>
        <translation>Auf eine Wand ausrichten</translation>
    </message>
    <message>
        <source>Put it beside a wall, on its right</source>
        <translation>Neben eine Wand stellen, rechts von ihm</translation>
    </message>
    <message>
        <source>Carry it 4 cm from the wall</source>
        <translation>4 cm vor die Wand tragen</translation>
    </message>
</context>
<context>
    <name>LessonFile</name>
    <message>
        <source>must be &quot;%1&quot;</source>
        <translation>muss &quot;%1&quot; sein</translation>
    </message>
    <message>
        <source>%1 is not a version this program reads (it reads %2)</source>
        <translation>%1 ist keine Version, die dieses Programm liest (es liest %2)</translation>
    </message>
    <message>
        <source>must be a list of at least one step</source>
        <translation>muss eine Liste mit mindestens einem Schritt sein</translation>
    </message>
    <message>
        <source>has more than %1 steps</source>
        <translation>hat mehr als %1 Schritte</translation>
    </message>
    <message>
        <source>step %1</source>
        <translation>Schritt %1</translation>
    </message>
    <message>
        <source>must be an object</source>
        <translation>muss ein Objekt sein</translation>
    </message>
    <message>
        <source>%1 is not a part of the robot diagram (%2)</source>
        <translation>%1 ist kein Teil der Roboterzeichnung (%2)</translation>
    </message>
    <message>
        <source>%1 is not a packet key</source>
        <translation>%1 ist kein Paketschlüssel</translation>
    </message>
    <message>
        <source>is missing or not an object</source>
        <translation>fehlt oder ist kein Objekt</translation>
    </message>
    <message>
        <source>needs exactly one of &quot;packet&quot;, &quot;drive_mm&quot;, &quot;turn_degrees&quot;, &quot;any&quot; or &quot;all&quot;</source>
        <translation>braucht genau eines von &quot;packet&quot;, &quot;drive_mm&quot;, &quot;turn_degrees&quot;, &quot;any&quot; oder &quot;all&quot;</translation>
    </message>
    <message>
        <source>must be a list of at least two goals</source>
        <translation>muss eine Liste mit mindestens zwei Zielen sein</translation>
    </message>
    <message>
        <source>needs &quot;bit&quot;, &quot;above&quot;, &quot;below&quot;, &quot;equals&quot; or &quot;ir&quot; with &quot;packet&quot;</source>
        <translation>braucht &quot;bit&quot;, &quot;above&quot;, &quot;below&quot;, &quot;equals&quot; oder &quot;ir&quot; zu &quot;packet&quot;</translation>
    </message>
    <message>
        <source>%1 is not a bit of %2</source>
        <translation>%1 ist kein Bit von %2</translation>
    </message>
    <message>
        <source>%1 is not an IR kind (dock, virtual_wall or any)</source>
        <translation>%1 ist keine IR-Art (dock, virtual_wall oder any)</translation>
    </message>
    <message>
        <source>needs an IR packet (ir_omni, ir_left or ir_right)</source>
        <translation>braucht ein IR-Paket (ir_omni, ir_left oder ir_right)</translation>
    </message>
    <message>
        <source>is not a field of a lesson file</source>
        <translation>ist kein Feld einer Lektionsdatei</translation>
    </message>
    <message>
        <source>must be a text that is not empty</source>
        <translation>muss ein nicht leerer Text sein</translation>
    </message>
    <message>
        <source>must be a list of texts</source>
        <translation>muss eine Liste von Texten sein</translation>
    </message>
    <message>
        <source>%1 must be a number from %2 to %3</source>
        <translation>%1 muss eine Zahl von %2 bis %3 sein</translation>
    </message>
    <message>
        <source>&quot;%1&quot; %2</source>
        <translation>&quot;%1&quot; %2</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1, &quot;%2&quot; %3</source>
        <translation>%1, &quot;%2&quot; %3</translation>
    </message>
    <message>
        <source>line %1: %2</source>
        <translation>Zeile %1: %2</translation>
    </message>
    <message>
        <source>not a JSON object</source>
        <translation>kein JSON-Objekt</translation>
    </message>
    <message>
        <source>needs &quot;place&quot; or &quot;forward_mm&quot;, not both</source>
        <translation>braucht &quot;place&quot; oder &quot;forward_mm&quot;, nicht beides</translation>
    </message>
    <message>
        <source>needs &quot;place&quot;, &quot;forward_mm&quot; or &quot;lift&quot;</source>
        <translation>braucht &quot;place&quot;, &quot;forward_mm&quot; oder &quot;lift&quot;</translation>
    </message>
    <message>
        <source>must be [x_mm, y_mm, heading_degrees], x and y from -%1 to %1, the heading from -360 to 360</source>
        <translation>muss [x_mm, y_mm, richtung_grad] sein, x und y von -%1 bis %1, die Richtung von -360 bis 360</translation>
    </message>
    <message>
        <source>must be true or false</source>
        <translation>muss true oder false sein</translation>
    </message>
    <message>
        <source>%1 or %2</source>
        <translation>%1 oder %2</translation>
    </message>
    <message>
        <source>%1 is not a robot (%2)</source>
        <translation>%1 ist kein Roboter (%2)</translation>
    </message>
</context>
<context>
    <name>LessonPanel</name>
    <message>
        <source>This lesson cannot be opened: %1</source>
        <translation>Diese Lektion lässt sich nicht öffnen: %1</translation>
    </message>
    <message>
        <source>Open lesson</source>
        <translation>Lektion öffnen</translation>
    </message>
    <message>
        <source>Lessons (*.json);;All files (*)</source>
        <translation>Lektionen (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Choose a lesson…</source>
        <translation>Lektion wählen…</translation>
    </message>
    <message>
        <source>Choose a lesson above, or open a lesson file. Each step says what to do and turns green when the robot shows it was done.</source>
        <translation>Wählen Sie oben eine Lektion oder öffnen Sie eine Lektionsdatei. Jeder Schritt sagt, was zu tun ist, und wird grün, wenn der Roboter zeigt, dass es getan ist.</translation>
    </message>
    <message>
        <source>Lesson complete: every step is done. Well done!</source>
        <translation>Lektion geschafft: Alle Schritte sind erledigt. Gut gemacht!</translation>
    </message>
    <message>
        <source>This lesson needs a robot this one is not (%1): some goals cannot be met.</source>
        <translation>Diese Lektion braucht einen anderen Roboter (%1): Manche Ziele sind nicht erreichbar.</translation>
    </message>
    <message>
        <source>No robot is selected: the goals are checked on the selected robot&apos;s data.</source>
        <translation>Kein Roboter ausgewählt: Die Ziele werden an den Daten des ausgewählten Roboters geprüft.</translation>
    </message>
    <message>
        <source>Open lesson file…</source>
        <translation>Lektionsdatei öffnen…</translation>
    </message>
    <message>
        <source>◀ Back</source>
        <translation>◀ Zurück</translation>
    </message>
    <message>
        <source>Skip ▶</source>
        <translation>Überspringen ▶</translation>
    </message>
    <message>
        <source>Restart</source>
        <translation>Neu beginnen</translation>
    </message>
    <message>
        <source>Lesson</source>
        <translation>Lektion</translation>
    </message>
    <message>
        <source>Lesson steps</source>
        <translation>Schritte der Lektion</translation>
    </message>
</context>
<context>
    <name>LessonStepView</name>
    <message>
        <source>Step %1 of %2</source>
        <translation>Schritt %1 von %2</translation>
    </message>
    <message>
        <source>Goal: %1</source>
        <translation>Ziel: %1</translation>
    </message>
    <message>
        <source>only on the virtual robot</source>
        <translation>nur beim virtuellen Roboter</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source> or </source>
        <translation> oder </translation>
    </message>
    <message>
        <source> and </source>
        <translation> und </translation>
    </message>
    <message>
        <source>drive %1 mm</source>
        <translation>%1 mm fahren</translation>
    </message>
    <message>
        <source>turn %1°</source>
        <translation>%1° drehen</translation>
    </message>
    <message>
        <source>%1 (this robot has no such sensor)</source>
        <translation>%1 (dieser Roboter hat keinen solchen Sensor)</translation>
    </message>
    <message>
        <source>%1 on</source>
        <translation>%1 an</translation>
    </message>
    <message>
        <source>%1 between %2 and %3</source>
        <translation>%1 zwischen %2 und %3</translation>
    </message>
    <message>
        <source>%1 above %2</source>
        <translation>%1 über %2</translation>
    </message>
    <message>
        <source>%1 below %2</source>
        <translation>%1 unter %2</translation>
    </message>
    <message>
        <source>%1 = %2</source>
        <translation>%1 = %2</translation>
    </message>
    <message>
        <source>%1 sees the dock</source>
        <translation>%1 sieht das Dock</translation>
    </message>
    <message>
        <source>%1 sees a virtual wall</source>
        <translation>%1 sieht eine virtuelle Wand</translation>
    </message>
    <message>
        <source>%1 sees any IR</source>
        <translation>%1 sieht irgendein IR</translation>
    </message>
    <message>
        <source>%1 for %2 s</source>
        <translation>%1 für %2 s</translation>
    </message>
    <message>
        <source>Driven, by odometry</source>
        <translation>Gefahren, laut Odometrie</translation>
    </message>
    <message>
        <source>Turned, by odometry</source>
        <translation>Gedreht, laut Odometrie</translation>
    </message>
    <message>
        <source>Driven, true</source>
        <translation>Gefahren, wirklich</translation>
    </message>
    <message>
        <source>Turned, true</source>
        <translation>Gedreht, wirklich</translation>
    </message>
    <message>
        <source>%p %</source>
        <translation>%p %</translation>
    </message>
    <message>
        <source>Done · next in %1 s</source>
        <translation>Erfüllt · weiter in %1 s</translation>
    </message>
    <message>
        <source>On the virtual robot: %1</source>
        <translation>Beim virtuellen Roboter: %1</translation>
    </message>
</context>
<context>
    <name>LinkSettings</name>
    <message>
        <source>replay of %1</source>
        <translation>Wiedergabe von %1</translation>
    </message>
    <message>
        <source>virtual %1</source>
        <translation>virtueller %1</translation>
    </message>
    <message>
        <source>%1 on the broker</source>
        <translation>%1 am Broker</translation>
    </message>
    <message>
        <source>%1: Baud is not sent over raw TCP: the bridge&apos;s serial rate cannot follow, and the robot would talk at a rate the bridge does not. Set the serial port&apos;s rate in ser2net&apos;s config instead (for example 115200 to 19200 on the robot&apos;s port line), then reconnect with the new rate; or use the bridge in RFC 2217 (telnet) mode, where the rate follows</source>
        <translation>%1: Baud wird über rohes TCP nicht gesendet: die serielle Rate der Brücke kann nicht folgen, und der Roboter spräche mit einer Rate, die die Brücke nicht spricht. Stellen Sie stattdessen die Rate des seriellen Ports in der Konfiguration von ser2net ein (zum Beispiel 115200 zu 19200 in der Zeile des Roboterports) und verbinden Sie sich dann mit der neuen Rate neu; oder betreiben Sie die Brücke im RFC-2217-Modus (Telnet), in dem die Rate folgt</translation>
    </message>
</context>
<context>
    <name>LiveServerActions</name>
    <message>
        <source>Live data server: dropped %1: %2</source>
        <translation>Live-Datenserver: %1 getrennt: %2</translation>
    </message>
    <message>
        <source>Live data server: refused %1, which %2; Foxglove, Lichtblick and PlotJuggler offer the right protocol</source>
        <translation>Live-Datenserver: %1 abgewiesen (%2); Foxglove, Lichtblick und PlotJuggler bieten das richtige Protokoll an</translation>
    </message>
    <message>
        <source>Live data server on %1: connect Foxglove or Lichtblick to it.</source>
        <translation>Live-Datenserver auf %1: verbinden Sie Foxglove oder Lichtblick damit.</translation>
    </message>
    <message>
        <source>Live data server on %1, reachable from other machines: anyone on the network can watch the robots.</source>
        <translation>Live-Datenserver auf %1, von anderen Rechnern erreichbar: jeder im Netzwerk kann die Roboter beobachten.</translation>
    </message>
    <message>
        <source>Live data server stopped.</source>
        <translation>Live-Datenserver beendet.</translation>
    </message>
    <message>
        <source>Address to paste into Foxglove or Lichtblick (Open connection → Foxglove WebSocket): %1</source>
        <translation>Adresse zum Einfügen in Foxglove oder Lichtblick (Open connection → Foxglove WebSocket): %1</translation>
    </message>
    <message>
        <source>Not serving.</source>
        <translation>Nicht aktiv.</translation>
    </message>
    <message>
        <source>Not serving: %1</source>
        <translation>Nicht aktiv: %1</translation>
    </message>
    <message>
        <source>Clients connected: %1</source>
        <translation>Verbundene Clients: %1</translation>
    </message>
    <message>
        <source>Still serving on the address before: %1</source>
        <translation>Weiter auf der bisherigen Adresse aktiv: %1</translation>
    </message>
    <message>
        <source>Only programs on this computer can connect.</source>
        <translation>Nur Programme auf diesem Computer können sich verbinden.</translation>
    </message>
    <message>
        <source>Reachable from other computers, as asked: anyone on the network can watch the robots. Use 127.0.0.1 to keep it on this computer.</source>
        <translation>Wie gewünscht von anderen Computern erreichbar: jeder im Netzwerk kann die Roboter beobachten. Mit 127.0.0.1 bleibt er auf diesem Computer.</translation>
    </message>
    <message>
        <source>&amp;Live data server…</source>
        <translation>&amp;Live-Datenserver…</translation>
    </message>
    <message>
        <source>Live data server</source>
        <translation>Live-Datenserver</translation>
    </message>
    <message>
        <source>Serves every robot&apos;s telemetry, pose, events and markers over the Foxglove WebSocket protocol, for Foxglove, Lichtblick and PlotJuggler.</source>
        <translation>Stellt Telemetrie, Pose, Ereignisse und Marker jedes Roboters über das Foxglove-WebSocket-Protokoll bereit, für Foxglove, Lichtblick und PlotJuggler.</translation>
    </message>
    <message>
        <source>Serve live data</source>
        <translation>Live-Daten bereitstellen</translation>
    </message>
    <message>
        <source>Address and port:</source>
        <translation>Adresse und Port:</translation>
    </message>
    <message>
        <source>Messages a second per channel:</source>
        <translation>Nachrichten pro Sekunde und Kanal:</translation>
    </message>
    <message>
        <source>Live data server: %1. The robots go on without it; choose another port in View → Live data server….</source>
        <translation>Live-Datenserver: %1. Die Roboter laufen ohne ihn weiter; wählen Sie unter Ansicht → Live-Datenserver… einen anderen Port.</translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <source>Connection</source>
        <translation>Verbindung</translation>
    </message>
    <message>
        <source>Modes</source>
        <translation>Modi</translation>
    </message>
    <message>
        <source>Drive</source>
        <translation>Fahren</translation>
    </message>
    <message>
        <source>Gauges</source>
        <translation>Messanzeigen</translation>
    </message>
    <message>
        <source>Signals</source>
        <translation>Signale</translation>
    </message>
    <message>
        <source>Plots</source>
        <translation>Diagramme</translation>
    </message>
    <message>
        <source>Inspector</source>
        <translation>Inspektor</translation>
    </message>
    <message>
        <source>Songs</source>
        <translation>Lieder</translation>
    </message>
    <message>
        <source>LEDs and digits</source>
        <translation>LEDs und Ziffern</translation>
    </message>
    <message>
        <source>Schedule</source>
        <translation>Zeitplan</translation>
    </message>
    <message>
        <source>Script</source>
        <translation>Skript</translation>
    </message>
    <message>
        <source>Motors and outputs</source>
        <translation>Motoren und Ausgänge</translation>
    </message>
    <message>
        <source>Odometry map</source>
        <translation>Odometriekarte</translation>
    </message>
    <message>
        <source>Gamepad</source>
        <translation>Gamepad</translation>
    </message>
    <message>
        <source>About Roomba Dashboard</source>
        <translation>Über Roomba Dashboard</translation>
    </message>
    <message>
        <source>Roomba Dashboard %1
A dashboard for iRobot robots that speak the Open Interface.
GPL-3.0-or-later.</source>
        <translation>Roomba Dashboard %1
Ein Dashboard für iRobot-Roboter, die das Open Interface sprechen.
GPL-3.0-or-later.</translation>
    </message>
    <message>
        <source>Roomba Dashboard</source>
        <translation>Roomba Dashboard</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;About</source>
        <translation>&amp;Über</translation>
    </message>
    <message>
        <source>%1 — Roomba Dashboard</source>
        <translation>%1 — Roomba Dashboard</translation>
    </message>
    <message>
        <source>Lesson</source>
        <translation>Lektion</translation>
    </message>
    <message>
        <source>&amp;Robot</source>
        <translation>&amp;Roboter</translation>
    </message>
    <message>
        <source>Markers</source>
        <translation>Markierungen</translation>
    </message>
    <message>
        <source>Typed into a text field: click the robot diagram or press Esc to drive with the keys</source>
        <translation>In ein Textfeld getippt: Klicken Sie auf das Roboterbild oder drücken Sie Esc, um mit den Tasten zu fahren</translation>
    </message>
    <message>
        <source>Typed into “%1”: click the robot diagram or press Esc to drive with the keys</source>
        <translation>In „%1“ getippt: Klicken Sie auf das Roboterbild oder drücken Sie Esc, um mit den Tasten zu fahren</translation>
    </message>
</context>
<context>
    <name>MarkerActions</name>
    <message>
        <source>Mark</source>
        <translation>Markieren</translation>
    </message>
    <message>
        <source>Drop a marker on the recording here, with an optional note (M)</source>
        <translation>Hier eine Markierung in die Aufzeichnung setzen, mit einer Notiz nach Wunsch (M)</translation>
    </message>
    <message>
        <source>Markers are kept in a recording: start one (File → Record) or open one. Then M marks the moment.</source>
        <translation>Markierungen werden in einer Aufzeichnung gespeichert: Starten Sie eine (Datei → Aufzeichnen) oder öffnen Sie eine. Dann markiert M den Moment.</translation>
    </message>
    <message>
        <source>Marker %1 at %2:</source>
        <translation>Markierung %1 bei %2:</translation>
    </message>
    <message>
        <source>Lesson step %1 done</source>
        <translation>Lektionsschritt %1 erledigt</translation>
    </message>
    <message>
        <source>Mark &amp;this moment</source>
        <translation>Diesen Moment mar&amp;kieren</translation>
    </message>
    <message>
        <source>Previo&amp;us marker</source>
        <translation>&amp;Vorige Markierung</translation>
    </message>
    <message>
        <source>&amp;Next marker</source>
        <translation>&amp;Nächste Markierung</translation>
    </message>
</context>
<context>
    <name>MarkerList</name>
    <message>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>Notiz</translation>
    </message>
    <message>
        <source>&amp;Jump</source>
        <translation>&amp;Springen</translation>
    </message>
    <message>
        <source>Go to the selected marker in the replay</source>
        <translation>In der Wiedergabe zur ausgewählten Markierung gehen</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Löschen</translation>
    </message>
    <message>
        <source>Delete the selected marker</source>
        <translation>Die ausgewählte Markierung löschen</translation>
    </message>
</context>
<context>
    <name>MarkerNoteEditor</name>
    <message>
        <source>a short note, then Enter</source>
        <translation>eine kurze Notiz, dann Enter</translation>
    </message>
    <message>
        <source>The marker is already set; a note is optional</source>
        <translation>Die Markierung ist schon gesetzt; eine Notiz ist freiwillig</translation>
    </message>
</context>
<context>
    <name>MeasuredMove</name>
    <message>
        <source>Forward</source>
        <translation>Vorwärts</translation>
    </message>
    <message>
        <source>Backward</source>
        <translation>Rückwärts</translation>
    </message>
    <message>
        <source>Turn left</source>
        <translation>Links drehen</translation>
    </message>
    <message>
        <source>Turn right</source>
        <translation>Rechts drehen</translation>
    </message>
    <message>
        <source>Go</source>
        <translation>Los</translation>
    </message>
    <message>
        <source>The robot drives until its wheels have measured the distance or the turn, then stops. Space or Esc stops it sooner.</source>
        <translation>Der Roboter fährt, bis seine Räder die Strecke oder die Drehung gemessen haben, und hält dann an. Leertaste oder Esc halten ihn früher an.</translation>
    </message>
    <message>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Move exactly:</source>
        <translation>Genau fahren:</translation>
    </message>
    <message>
        <source>A move measured by the robot&apos;s own wheels, as a student&apos;s program makes it.</source>
        <translation>Eine Fahrt, gemessen von den eigenen Rädern des Roboters, wie ein Schülerprogramm sie macht.</translation>
    </message>
</context>
<context>
    <name>MeasuredMoves</name>
    <message>
        <source>Not moving: a classroom robot&apos;s measured moves run on its bridge, beside the robot (the Python library&apos;s straight() and turn()). Drive it with the pad or the keys here.</source>
        <translation>Keine Fahrt: Die gemessenen Fahrten eines Klassenraum-Roboters laufen auf seiner Bridge neben dem Roboter (straight() und turn() der Python-Bibliothek). Fahren Sie ihn hier mit dem Steuerfeld oder den Tasten.</translation>
    </message>
    <message>
        <source>Not moving: no live data from the robot, so its wheels cannot measure the move. Connect it and wait until it streams.</source>
        <translation>Keine Fahrt: keine aktuellen Daten vom Roboter, also können seine Räder die Fahrt nicht messen. Verbinden Sie ihn und warten Sie, bis er sendet.</translation>
    </message>
    <message>
        <source>Not moving: the robot&apos;s model is not known yet. Wait a moment and press Go again.</source>
        <translation>Keine Fahrt: Das Modell des Roboters ist noch nicht bekannt. Warten Sie einen Moment und drücken Sie erneut Los.</translation>
    </message>
    <message>
        <source>Not moving: the robot is in Passive mode and ignores motion. Press Enter Safe, then Go.</source>
        <translation>Keine Fahrt: Der Roboter ist im Passiv-Modus und ignoriert Fahrbefehle. Drücken Sie Safe aktivieren, dann Los.</translation>
    </message>
    <message>
        <source>Moving %1 mm at %2 mm/s…</source>
        <translation>Fährt %1 mm mit %2 mm/s…</translation>
    </message>
    <message>
        <source>Turning %1° at %2°/s…</source>
        <translation>Dreht %1° mit %2°/s…</translation>
    </message>
    <message>
        <source>%1 mm measured</source>
        <translation>%1 mm gemessen</translation>
    </message>
    <message>
        <source>%1° measured</source>
        <translation>%1° gemessen</translation>
    </message>
    <message>
        <source>Done: asked %1 mm, %2.</source>
        <translation>Fertig: %1 mm verlangt, %2.</translation>
    </message>
    <message>
        <source>Done: asked %1°, %2.</source>
        <translation>Fertig: %1° verlangt, %2.</translation>
    </message>
    <message>
        <source>Stopped early by the robot itself (a cliff or a wheel drop; the Modes dock says which): %1.</source>
        <translation>Vom Roboter selbst früher angehalten (ein Abgrund oder ein abgesenktes Rad; das Modi-Fenster sagt, welches): %1.</translation>
    </message>
    <message>
        <source>Stopped early: another command or a stop ended the move (%1).</source>
        <translation>Früher angehalten: Ein anderer Befehl oder ein Stopp hat die Fahrt beendet (%1).</translation>
    </message>
    <message>
        <source>Stopped: the move took too long, as if the robot pushed against something (%1). Look at what is in its way.</source>
        <translation>Angehalten: Die Fahrt dauerte zu lange, als ob der Roboter gegen etwas drückt (%1). Sehen Sie nach, was ihm im Weg ist.</translation>
    </message>
    <message>
        <source>Stopped: the robot&apos;s data stopped coming (%1). Check its connection.</source>
        <translation>Angehalten: Die Daten des Roboters kommen nicht mehr (%1). Prüfen Sie seine Verbindung.</translation>
    </message>
</context>
<context>
    <name>MidiMelody</name>
    <message>
        <source>Could not import %1: %2</source>
        <translation>%1 konnte nicht importiert werden: %2</translation>
    </message>
    <message>
        <source>not a readable Standard MIDI File</source>
        <translation>keine lesbare Standard-MIDI-Datei</translation>
    </message>
    <message>
        <source>it has no notes</source>
        <translation>sie enthält keine Noten</translation>
    </message>
    <message>
        <source>its notes are all shorter than 1/64 s</source>
        <translation>alle ihre Noten sind kürzer als 1/64 s</translation>
    </message>
</context>
<context>
    <name>ModePanel</name>
    <message>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <source>Passive</source>
        <translation>Passive</translation>
    </message>
    <message>
        <source>Safe</source>
        <translation>Safe</translation>
    </message>
    <message>
        <source>Full</source>
        <translation>Full</translation>
    </message>
    <message>
        <source>Enter Full mode?</source>
        <translation>In den Modus Full wechseln?</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Reset</translation>
    </message>
    <message>
        <source>Power off</source>
        <translation>Ausschalten</translation>
    </message>
    <message>
        <source>Clean</source>
        <translation>Reinigen</translation>
    </message>
    <message>
        <source>Spot</source>
        <translation>Spot</translation>
    </message>
    <message>
        <source>Max</source>
        <translation>Max</translation>
    </message>
    <message>
        <source>Seek Dock</source>
        <translation>Dock suchen</translation>
    </message>
    <message>
        <source>Cover</source>
        <translation>Flächenabdeckung</translation>
    </message>
    <message>
        <source>Cover and Dock</source>
        <translation>Flächenabdeckung und Andocken</translation>
    </message>
    <message>
        <source>Demo</source>
        <translation>Demo</translation>
    </message>
    <message>
        <source>Demo to run</source>
        <translation>Auszuführende Demo</translation>
    </message>
    <message>
        <source>%1 (opcode %2)</source>
        <translation>%1 (Opcode %2)</translation>
    </message>
    <message>
        <source>%1 is not available on the %2</source>
        <translation>%1 ist beim %2 nicht verfügbar</translation>
    </message>
    <message>
        <source>Mode: %1</source>
        <translation>Modus: %1</translation>
    </message>
    <message>
        <source>Mode: unknown</source>
        <translation>Modus: unbekannt</translation>
    </message>
    <message>
        <source>Firmware: %1</source>
        <translation>Firmware: %1</translation>
    </message>
    <message>
        <source>mode %1 (not an OI mode)</source>
        <translation>Modus %1 (kein OI-Modus)</translation>
    </message>
    <message>
        <source>Full mode turns off the cliff, wheel-drop and charger safety stops. The robot will drive off a table edge if told to. It is also the way off the dock, where Safe is refused (on the dock it does not charge in Full). Enter Full mode?</source>
        <translation>Der Full-Modus schaltet die Sicherheitsstopps für Abgrund, Radabsenkung und Ladegerät ab. Der Roboter fährt auf Befehl auch über eine Tischkante. Er ist auch der Weg von der Ladestation herunter, wo Safe verweigert wird (auf der Ladestation lädt er im Full-Modus nicht). Full-Modus einschalten?</translation>
    </message>
</context>
<context>
    <name>MotorsPanel</name>
    <message>
        <source>Motors</source>
        <translation>Motors</translation>
    </message>
    <message>
        <source>PWM Motors</source>
        <translation>PWM Motors</translation>
    </message>
    <message>
        <source>Buttons</source>
        <translation>Buttons</translation>
    </message>
    <message>
        <source>Low Side Drivers</source>
        <translation>Low Side Drivers</translation>
    </message>
    <message>
        <source>PWM Low Side Drivers</source>
        <translation>PWM Low Side Drivers</translation>
    </message>
    <message>
        <source>Digital Outputs</source>
        <translation>Digital Outputs</translation>
    </message>
    <message>
        <source>Send IR</source>
        <translation>Send IR</translation>
    </message>
    <message>
        <source>Clean</source>
        <translation>Clean</translation>
    </message>
    <message>
        <source>Spot</source>
        <translation>Spot</translation>
    </message>
    <message>
        <source>Dock</source>
        <translation>Dock</translation>
    </message>
    <message>
        <source>Minute</source>
        <translation>Minute</translation>
    </message>
    <message>
        <source>Hour</source>
        <translation>Stunde</translation>
    </message>
    <message>
        <source>Day</source>
        <translation>Tag</translation>
    </message>
    <message>
        <source>Schedule</source>
        <translation>Zeitplan</translation>
    </message>
    <message>
        <source>Clock</source>
        <translation>Uhr</translation>
    </message>
    <message>
        <source>Brushes and vacuum — Motors (138)</source>
        <translation>Bürsten und Sauger — Motors (138)</translation>
    </message>
    <message>
        <source>Main brush</source>
        <translation>Hauptbürste</translation>
    </message>
    <message>
        <source>Outward</source>
        <translation>Nach außen</translation>
    </message>
    <message>
        <source>Side brush</source>
        <translation>Seitenbürste</translation>
    </message>
    <message>
        <source>Clockwise</source>
        <translation>Im Uhrzeigersinn</translation>
    </message>
    <message>
        <source>Vacuum</source>
        <translation>Sauger</translation>
    </message>
    <message>
        <source>Duty cycle — PWM Motors (144)</source>
        <translation>Tastverhältnis — PWM Motors (144)</translation>
    </message>
    <message>
        <source>Brushes -127..127 (negative turns them the other way), vacuum 0..127; 127 is full power.</source>
        <translation>Bürsten -127..127 (negativ dreht sie andersherum), Sauger 0..127; 127 ist volle Leistung.</translation>
    </message>
    <message>
        <source>Press a button — Buttons (165)</source>
        <translation>Taste drücken — Buttons (165)</translation>
    </message>
    <message>
        <source>Low side drivers — Low Side Drivers (138)</source>
        <translation>Low-Side-Treiber — Low Side Drivers (138)</translation>
    </message>
    <message>
        <source>Duty cycle — PWM Low Side Drivers (144)</source>
        <translation>Tastverhältnis — PWM Low Side Drivers (144)</translation>
    </message>
    <message>
        <source>LD%1</source>
        <translation>LD%1</translation>
    </message>
    <message>
        <source>0..128; 128 is 100%.</source>
        <translation>0..128; 128 entspricht 100 %.</translation>
    </message>
    <message>
        <source>Cargo bay — Digital Outputs (147)</source>
        <translation>Laderaum — Digital Outputs (147)</translation>
    </message>
    <message>
        <source>Output %1</source>
        <translation>Ausgang %1</translation>
    </message>
    <message>
        <source>IR output — Send IR (151)</source>
        <translation>IR-Ausgang — Send IR (151)</translation>
    </message>
    <message>
        <source>Byte</source>
        <translation>Byte</translation>
    </message>
    <message>
        <source>All off</source>
        <translation>Alles aus</translation>
    </message>
    <message>
        <source>Not on the %1, so not shown: %2.</source>
        <translation>Beim %1 nicht vorhanden, daher ausgeblendet: %2.</translation>
    </message>
    <message>
        <source>Last sent: —</source>
        <translation>Zuletzt gesendet: —</translation>
    </message>
    <message>
        <source>Last sent: %1</source>
        <translation>Zuletzt gesendet: %1</translation>
    </message>
</context>
<context>
    <name>NetworkTransport</name>
    <message>
        <source>%1 on the broker</source>
        <translation>%1 am Broker</translation>
    </message>
    <message>
        <source>%1: not connected to a broker</source>
        <translation>%1: mit keinem Broker verbunden</translation>
    </message>
    <message>
        <source>%1: the bridge takes commands, not bytes: check the connection where the bridge runs</source>
        <translation>%1: die Bridge nimmt Befehle an, keine Bytes: prüfen Sie die Verbindung dort, wo die Bridge läuft</translation>
    </message>
    <message>
        <source>%1: control was not given</source>
        <translation>%1: Steuerung wurde nicht erteilt</translation>
    </message>
    <message>
        <source>%1: %2 has control</source>
        <translation>%1: %2 hat die Steuerung</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1: the bridge does not publish packet %2, so the query cannot be answered</source>
        <translation>%1: die Bridge veröffentlicht Paket %2 nicht, daher kann die Abfrage nicht beantwortet werden</translation>
    </message>
    <message>
        <source>%1: the bridge does not read the robot&apos;s script back</source>
        <translation>%1: die Bridge liest das Skript des Roboters nicht zurück</translation>
    </message>
</context>
<context>
    <name>OdometryMap</name>
    <message>
        <source>Zoom in</source>
        <translation>Vergrößern</translation>
    </message>
    <message>
        <source>Zoom out</source>
        <translation>Verkleinern</translation>
    </message>
    <message>
        <source>Centre</source>
        <translation>Zentrieren</translation>
    </message>
    <message>
        <source>Centre the map on the robot</source>
        <translation>Karte auf den Roboter zentrieren</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <source>Clear the trail and start the odometry again at the origin</source>
        <translation>Spur löschen und die Odometrie im Ursprung neu beginnen</translation>
    </message>
    <message>
        <source>Wheel base</source>
        <translation>Radabstand</translation>
    </message>
    <message>
        <source>Wheel Ø</source>
        <translation>Rad-Ø</translation>
    </message>
    <message>
        <source>Odometry map</source>
        <translation>Odometriekarte</translation>
    </message>
    <message>
        <source>The %1 has no wheel encoders; it reports distance and angle itself</source>
        <translation>Der %1 hat keine Radencoder; er meldet Strecke und Winkel selbst</translation>
    </message>
    <message>
        <source>Distance between the wheels&apos; contact points</source>
        <translation>Abstand zwischen den Aufstandspunkten der Räder</translation>
    </message>
    <message>
        <source>Wheel diameter; 508.8 encoder counts are one turn</source>
        <translation>Raddurchmesser; 508,8 Encoderschritte sind eine Umdrehung</translation>
    </message>
    <message>
        <source>x %1 mm   y %2 mm   θ %3°</source>
        <translation>x %1 mm   y %2 mm   θ %3°</translation>
    </message>
    <message>
        <source>   drift %1 mm</source>
        <translation>   Drift %1 mm</translation>
    </message>
    <message>
        <source>Robot at x %1 mm, y %2 mm, heading %3 degrees</source>
        <translation>Roboter bei x %1 mm, y %2 mm, Ausrichtung %3 Grad</translation>
    </message>
    <message>
        <source>; %1 mm from the true pose</source>
        <translation>; %1 mm von der wahren Pose entfernt</translation>
    </message>
    <message>
        <source>odometry</source>
        <translation>Odometrie</translation>
    </message>
    <message>
        <source>true pose</source>
        <translation>wahre Pose</translation>
    </message>
    <message>
        <source>dock</source>
        <translation>Ladestation</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>Edit room</source>
        <translation>Raum bearbeiten</translation>
    </message>
    <message>
        <source>Move, add and delete the walls, stage edges, the dock and the virtual wall</source>
        <translation>Wände, Bühnenkanten, die Ladestation und die virtuelle Wand verschieben, hinzufügen und löschen</translation>
    </message>
    <message>
        <source>Robot not yet identified: a Roomba 500 or a Create 2? Until it is named, its wheel counts may read mirrored, so no path is drawn.</source>
        <translation>Roboter noch nicht bestimmt: ein Roomba 500 oder ein Create 2? Bis er benannt ist, können seine Radzähler gespiegelt gelesen werden, darum wird kein Weg gezeichnet.</translation>
    </message>
    <message>
        <source>comparison run</source>
        <translation>Vergleichsfahrt</translation>
    </message>
    <message>
        <source>wall</source>
        <translation>Wand</translation>
    </message>
    <message>
        <source>stage edge</source>
        <translation>Bühnenkante</translation>
    </message>
    <message>
        <source>virtual wall</source>
        <translation>virtuelle Wand</translation>
    </message>
</context>
<context>
    <name>PacketName</name>
    <message>
        <source>Angle</source>
        <translation>Winkel</translation>
    </message>
    <message>
        <source>Battery Capacity</source>
        <translation>Akkukapazität</translation>
    </message>
    <message>
        <source>Battery Charge</source>
        <translation>Akkuladung</translation>
    </message>
    <message>
        <source>Bumps and Wheel Drops</source>
        <translation>Stöße und Radabsenkungen</translation>
    </message>
    <message>
        <source>Buttons</source>
        <translation>Tasten</translation>
    </message>
    <message>
        <source>Cargo Bay Analog Signal</source>
        <translation>Laderaum-Analogsignal</translation>
    </message>
    <message>
        <source>Cargo Bay Digital Inputs</source>
        <translation>Laderaum-Digitaleingänge</translation>
    </message>
    <message>
        <source>Charging Sources Available</source>
        <translation>Verfügbare Ladequellen</translation>
    </message>
    <message>
        <source>Charging State</source>
        <translation>Ladezustand</translation>
    </message>
    <message>
        <source>Cliff Front Left</source>
        <translation>Abgrund vorne links</translation>
    </message>
    <message>
        <source>Cliff Front Left Signal</source>
        <translation>Abgrundsignal vorne links</translation>
    </message>
    <message>
        <source>Cliff Front Right</source>
        <translation>Abgrund vorne rechts</translation>
    </message>
    <message>
        <source>Cliff Front Right Signal</source>
        <translation>Abgrundsignal vorne rechts</translation>
    </message>
    <message>
        <source>Cliff Left</source>
        <translation>Abgrund links</translation>
    </message>
    <message>
        <source>Cliff Left Signal</source>
        <translation>Abgrundsignal links</translation>
    </message>
    <message>
        <source>Cliff Right</source>
        <translation>Abgrund rechts</translation>
    </message>
    <message>
        <source>Cliff Right Signal</source>
        <translation>Abgrundsignal rechts</translation>
    </message>
    <message>
        <source>Current</source>
        <translation>Strom</translation>
    </message>
    <message>
        <source>Dirt Detect</source>
        <translation>Schmutzerkennung</translation>
    </message>
    <message>
        <source>Distance</source>
        <translation>Strecke</translation>
    </message>
    <message>
        <source>Infrared Character Left</source>
        <translation>Infrarotzeichen links</translation>
    </message>
    <message>
        <source>Infrared Character Right</source>
        <translation>Infrarotzeichen rechts</translation>
    </message>
    <message>
        <source>Left Encoder Counts</source>
        <translation>Encoderzähler links</translation>
    </message>
    <message>
        <source>Left Motor Current</source>
        <translation>Motorstrom links</translation>
    </message>
    <message>
        <source>Light Bump Center Left Signal</source>
        <translation>Lichtstoßfängersignal Mitte links</translation>
    </message>
    <message>
        <source>Light Bump Center Right Signal</source>
        <translation>Lichtstoßfängersignal Mitte rechts</translation>
    </message>
    <message>
        <source>Light Bump Front Left Signal</source>
        <translation>Lichtstoßfängersignal vorne links</translation>
    </message>
    <message>
        <source>Light Bump Front Right Signal</source>
        <translation>Lichtstoßfängersignal vorne rechts</translation>
    </message>
    <message>
        <source>Light Bump Left Signal</source>
        <translation>Lichtstoßfängersignal links</translation>
    </message>
    <message>
        <source>Light Bump Right Signal</source>
        <translation>Lichtstoßfängersignal rechts</translation>
    </message>
    <message>
        <source>Light Bumper</source>
        <translation>Lichtstoßfänger</translation>
    </message>
    <message>
        <source>Main Brush Motor Current</source>
        <translation>Hauptbürsten-Motorstrom</translation>
    </message>
    <message>
        <source>Number of Stream Packets</source>
        <translation>Anzahl Datenstrompakete</translation>
    </message>
    <message>
        <source>OI Mode</source>
        <translation>OI-Modus</translation>
    </message>
    <message>
        <source>Overcurrents</source>
        <translation>Überströme</translation>
    </message>
    <message>
        <source>Requested Left Velocity</source>
        <translation>Angeforderte Geschwindigkeit links</translation>
    </message>
    <message>
        <source>Requested Radius</source>
        <translation>Angeforderter Radius</translation>
    </message>
    <message>
        <source>Requested Right Velocity</source>
        <translation>Angeforderte Geschwindigkeit rechts</translation>
    </message>
    <message>
        <source>Requested Velocity</source>
        <translation>Angeforderte Geschwindigkeit</translation>
    </message>
    <message>
        <source>Right Encoder Counts</source>
        <translation>Encoderzähler rechts</translation>
    </message>
    <message>
        <source>Right Motor Current</source>
        <translation>Motorstrom rechts</translation>
    </message>
    <message>
        <source>Side Brush Motor Current</source>
        <translation>Seitenbürsten-Motorstrom</translation>
    </message>
    <message>
        <source>Song Number</source>
        <translation>Liednummer</translation>
    </message>
    <message>
        <source>Song Playing</source>
        <translation>Lied wird gespielt</translation>
    </message>
    <message>
        <source>Stasis</source>
        <translation>Stasis</translation>
    </message>
    <message>
        <source>Temperature</source>
        <translation>Temperatur</translation>
    </message>
    <message>
        <source>Unused</source>
        <translation>Unbenutzt</translation>
    </message>
    <message>
        <source>Virtual Wall</source>
        <translation>Virtuelle Wand</translation>
    </message>
    <message>
        <source>Voltage</source>
        <translation>Spannung</translation>
    </message>
    <message>
        <source>Wall</source>
        <translation>Wand</translation>
    </message>
    <message>
        <source>Wall Signal</source>
        <translation>Wandsignal</translation>
    </message>
    <message>
        <source>Infrared Character Omni</source>
        <translation>Infrarotzeichen rundum</translation>
    </message>
    <message>
        <source>Infrared Byte</source>
        <translation>Infrarot-Byte</translation>
    </message>
</context>
<context>
    <name>PacketTable</name>
    <message>
        <source>Packets</source>
        <translation>Pakete</translation>
    </message>
    <message>
        <source>Plot</source>
        <translation>Plotten</translation>
    </message>
    <message>
        <source>Plot the chosen packet (or double-click its row)</source>
        <translation>Das gewählte Paket plotten (oder seine Zeile doppelklicken)</translation>
    </message>
</context>
<context>
    <name>PacketTableModel</name>
    <message>
        <source>Id</source>
        <translation>Nr.</translation>
    </message>
    <message>
        <source>Packet</source>
        <translation>Paket</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Raw</source>
        <translation>Roh</translation>
    </message>
    <message>
        <source>Rate</source>
        <translation>Rate</translation>
    </message>
</context>
<context>
    <name>PianoRoll</name>
    <message>
        <source>rest</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Click to add a note, drag a note to move it, drag its right edge to lengthen it</source>
        <translation>Klicken fügt eine Note hinzu, Ziehen verschiebt eine Note, Ziehen am rechten Rand verlängert sie</translation>
    </message>
    <message>
        <source>Piano roll</source>
        <translation>Pianorolle</translation>
    </message>
    <message>
        <source>1 note, %1 s.</source>
        <translation>1 Note, %1 s.</translation>
    </message>
    <message numerus="yes">
        <source>%n notes, %1 s.</source>
        <translation>
            <numerusform>%n Note, %1 s.</numerusform>
            <numerusform>%n Noten, %1 s.</numerusform>
        </translation>
    </message>
    <message>
        <source>Selected: note %1, %2, %3/64 s.</source>
        <translation>Ausgewählt: Note %1, %2, %3/64 s.</translation>
    </message>
    <message>
        <source>Left and Right select a note, Up and Down change its pitch, Shift+Left and Shift+Right its length, Insert adds a note, Delete removes one.</source>
        <translation>Links und Rechts wählen eine Note, Auf und Ab ändern ihre Tonhöhe, Umschalt+Links und Umschalt+Rechts ihre Länge, Einfg fügt eine Note ein, Entf entfernt eine.</translation>
    </message>
    <message>
        <source>A song holds at most %1 notes; remove one first</source>
        <translation>Ein Lied fasst höchstens %1 Noten; entfernen Sie zuerst eine</translation>
    </message>
</context>
<context>
    <name>PlotStack</name>
    <message>
        <source>Remove this plot</source>
        <translation>Dieses Diagramm entfernen</translation>
    </message>
    <message>
        <source>Sensor plot</source>
        <translation>Sensordiagramm</translation>
    </message>
    <message>
        <source>Choose the channels to plot with the button above</source>
        <translation>Wählen Sie die Kanäle mit der Schaltfläche oben</translation>
    </message>
    <message>
        <source>No samples in this time range</source>
        <translation>Keine Messwerte in diesem Zeitbereich</translation>
    </message>
    <message>
        <source>Waiting for samples</source>
        <translation>Warten auf Messwerte</translation>
    </message>
    <message>
        <source>%1 (unreliable)</source>
        <translation>%1 (unzuverlässig)</translation>
    </message>
    <message>
        <source>%1 (moved %2 s)</source>
        <translation>%1 (um %2 s verschoben)</translation>
    </message>
    <message>
        <source>No channels chosen</source>
        <translation>Keine Kanäle gewählt</translation>
    </message>
    <message>
        <source>Channels: %1</source>
        <translation>Kanäle: %1</translation>
    </message>
    <message>
        <source>, </source>
        <translation>, </translation>
    </message>
    <message>
        <source>%1. %2</source>
        <translation>%1. %2</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>ProjectorMode</name>
    <message>
        <source>&amp;Projector view</source>
        <translation>&amp;Projektoransicht</translation>
    </message>
    <message>
        <source>Large type, high contrast, the selected robot or the lesson alone (F11)</source>
        <translation>Große Schrift, hoher Kontrast, nur der ausgewählte Roboter oder die Lektion (F11)</translation>
    </message>
</context>
<context>
    <name>ProjectorView</name>
    <message>
        <source>battery %1 %</source>
        <translation>Akku %1 %</translation>
    </message>
    <message>
        <source>NO LIVE DATA</source>
        <translation>KEINE LIVE-DATEN</translation>
    </message>
    <message>
        <source>lesson complete</source>
        <translation>Lektion geschafft</translation>
    </message>
    <message>
        <source>F11: leave the projector view · Esc: stop the robot and leave</source>
        <translation>F11: Projektoransicht verlassen · Esc: Roboter anhalten und verlassen</translation>
    </message>
    <message>
        <source>Projector view</source>
        <translation>Projektoransicht</translation>
    </message>
    <message>
        <source>Enter Safe (Enter)</source>
        <translation>Safe aktivieren (Eingabe)</translation>
    </message>
    <message>
        <source>This step expects it: follow the step below.</source>
        <translation>Dieser Schritt erwartet das: Folgen Sie dem Schritt unten.</translation>
    </message>
</context>
<context>
    <name>Recording</name>
    <message>
        <source>cannot create the recording</source>
        <translation>Aufzeichnung kann nicht angelegt werden</translation>
    </message>
    <message>
        <source>cannot write</source>
        <translation>Schreiben nicht möglich</translation>
    </message>
    <message>
        <source>%1 at byte %2 (record %3, after %4 s)</source>
        <translation>%1 bei Byte %2 (Eintrag %3, nach %4 s)</translation>
    </message>
    <message>
        <source>not a Roomba Dashboard recording</source>
        <translation>keine Aufzeichnung von Roomba Dashboard</translation>
    </message>
    <message>
        <source>the header is truncated</source>
        <translation>der Kopf ist abgeschnitten</translation>
    </message>
    <message>
        <source>the header is not valid JSON: %1</source>
        <translation>der Kopf ist kein gültiges JSON: %1</translation>
    </message>
    <message>
        <source>truncated record</source>
        <translation>abgeschnittener Eintrag</translation>
    </message>
    <message>
        <source>checksum mismatch</source>
        <translation>Prüfsumme falsch</translation>
    </message>
    <message>
        <source>time runs backwards</source>
        <translation>die Zeit läuft rückwärts</translation>
    </message>
    <message>
        <source>unreadable stream description</source>
        <translation>unlesbare Beschreibung des Datenstroms</translation>
    </message>
    <message>
        <source>unknown record type 0x%1</source>
        <translation>unbekannter Eintragstyp 0x%1</translation>
    </message>
    <message>
        <source>damaged before the stream started: %1</source>
        <translation>beschädigt, bevor der Datenstrom begann: %1</translation>
    </message>
    <message>
        <source>the recording holds no sensor stream</source>
        <translation>die Aufzeichnung enthält keinen Sensordatenstrom</translation>
    </message>
    <message>
        <source>recording format version %1; this program reads versions %2 to %3</source>
        <translation>Aufzeichnungsformat Version %1; dieses Programm liest die Versionen %2 bis %3</translation>
    </message>
    <message>
        <source>unreadable marker</source>
        <translation>unlesbare Markierung</translation>
    </message>
    <message>
        <source>unreadable true pose</source>
        <translation>unlesbare wahre Pose</translation>
    </message>
    <message>
        <source>packet %1 is in it twice</source>
        <translation>Paket %1 kommt darin zweimal vor</translation>
    </message>
    <message>
        <source>a stream no robot sends (%1)</source>
        <translation>ein Datenstrom, den kein Roboter sendet (%1)</translation>
    </message>
</context>
<context>
    <name>RecordingActions</name>
    <message>
        <source>&amp;Record</source>
        <translation>&amp;Aufzeichnen</translation>
    </message>
    <message>
        <source>Record every byte to and from the selected robot into a file</source>
        <translation>Jedes Byte zum und vom ausgewählten Roboter in eine Datei aufzeichnen</translation>
    </message>
    <message>
        <source>&amp;Open recording…</source>
        <translation>Aufzeichnung ö&amp;ffnen…</translation>
    </message>
    <message>
        <source>Replay a recording as a robot of its own</source>
        <translation>Eine Aufzeichnung als eigenen Roboter wiedergeben</translation>
    </message>
    <message>
        <source>&amp;Export recording as CSV…</source>
        <translation>Aufzeichnung als CSV &amp;exportieren…</translation>
    </message>
    <message>
        <source>Record %1 to</source>
        <translation>%1 aufzeichnen nach</translation>
    </message>
    <message>
        <source>Roomba Dashboard recordings (*.oirec)</source>
        <translation>Roomba-Dashboard-Aufzeichnungen (*.oirec)</translation>
    </message>
    <message>
        <source>Open recording</source>
        <translation>Aufzeichnung öffnen</translation>
    </message>
    <message>
        <source>Roomba Dashboard recordings (*.oirec);;All files (*)</source>
        <translation>Roomba-Dashboard-Aufzeichnungen (*.oirec);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>This file cannot be replayed.

%1</source>
        <translation>Diese Datei kann nicht wiedergegeben werden.

%1</translation>
    </message>
    <message>
        <source>Export recording as CSV</source>
        <translation>Aufzeichnung als CSV exportieren</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
    <message>
        <source>Nothing was written.

%1</source>
        <translation>Es wurde nichts geschrieben.

%1</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>%1 geschrieben</translation>
    </message>
    <message>
        <source>Recording and replay</source>
        <translation>Aufzeichnung und Wiedergabe</translation>
    </message>
    <message>
        <source>Export recording as &amp;MCAP…</source>
        <translation>Aufzeichnung als &amp;MCAP exportieren…</translation>
    </message>
    <message>
        <source>For Foxglove, Lichtblick and PlotJuggler</source>
        <translation>Für Foxglove, Lichtblick und PlotJuggler</translation>
    </message>
    <message>
        <source>MCAP, zstd compression (*.mcap)</source>
        <translation>MCAP, mit zstd komprimiert (*.mcap)</translation>
    </message>
    <message>
        <source>MCAP, lz4 compression: quicker to open (*.mcap)</source>
        <translation>MCAP, mit lz4 komprimiert: schneller zu öffnen (*.mcap)</translation>
    </message>
    <message>
        <source>Export recording as MCAP</source>
        <translation>Aufzeichnung als MCAP exportieren</translation>
    </message>
    <message>
        <source>The recording is damaged; %1 holds everything up to the damage.

%2</source>
        <translation>Die Aufzeichnung ist beschädigt; %1 enthält alles bis zur beschädigten Stelle.

%2</translation>
    </message>
    <message>
        <source>Replay</source>
        <translation>Wiedergabe</translation>
    </message>
    <message>
        <source>Export another recording as CSV…</source>
        <translation>Eine andere Aufzeichnung als CSV exportieren…</translation>
    </message>
    <message>
        <source>Export another recording as MCAP…</source>
        <translation>Eine andere Aufzeichnung als MCAP exportieren…</translation>
    </message>
    <message>
        <source>The recording on screen: a replay, or the last recording of the selected robot</source>
        <translation>Die Aufzeichnung auf dem Bildschirm: eine Wiedergabe, oder die letzte Aufzeichnung des gewählten Roboters</translation>
    </message>
    <message>
        <source>Choose a recording file first, then where to write the CSV</source>
        <translation>Zuerst eine Aufzeichnungsdatei wählen, dann wohin die CSV geschrieben wird</translation>
    </message>
    <message>
        <source>Choose a recording file first, then where to write the MCAP file</source>
        <translation>Zuerst eine Aufzeichnungsdatei wählen, dann wohin die MCAP-Datei geschrieben wird</translation>
    </message>
    <message>
        <source>Choose the recording to export as %1</source>
        <translation>Die Aufzeichnung wählen, die als %1 exportiert wird</translation>
    </message>
    <message>
        <source>Export %1 as %2</source>
        <translation>%1 als %2 exportieren</translation>
    </message>
</context>
<context>
    <name>RecordingMarkers</name>
    <message>
        <source>%1 markers beyond the first %2 were left out: a recording holds at most %2</source>
        <translation>%1 Markierungen nach den ersten %2 wurden ausgelassen: eine Aufzeichnung fasst höchstens %2</translation>
    </message>
</context>
<context>
    <name>RemoteRobot</name>
    <message>
        <source>state: &quot;%1&quot; must be a string</source>
        <translation>Zustand: „%1“ muss eine Zeichenkette sein</translation>
    </message>
    <message>
        <source>state: &quot;online&quot; must be true or false</source>
        <translation>Zustand: „online“ muss true oder false sein</translation>
    </message>
    <message>
        <source>state: &quot;battery_percent&quot; must be a number</source>
        <translation>Zustand: „battery_percent“ muss eine Zahl sein</translation>
    </message>
    <message>
        <source>state: &quot;mode_cause&quot; must be a list of words</source>
        <translation>Zustand: „mode_cause“ muss eine Liste von Wörtern sein</translation>
    </message>
    <message>
        <source>state: &quot;battery&quot; must be an object</source>
        <translation>Zustand: „battery“ muss ein Objekt sein</translation>
    </message>
</context>
<context>
    <name>ReplayBar</name>
    <message>
        <source>One frame back</source>
        <translation>Ein Frame zurück</translation>
    </message>
    <message>
        <source>One frame forward</source>
        <translation>Ein Frame vor</translation>
    </message>
    <message>
        <source>Replay speed</source>
        <translation>Wiedergabegeschwindigkeit</translation>
    </message>
    <message>
        <source>Position in the recording</source>
        <translation>Position in der Aufzeichnung</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Abspielen</translation>
    </message>
    <message>
        <source>%1 / %2, frame %3 of %4</source>
        <translation>%1 / %2, Frame %3 von %4</translation>
    </message>
    <message>
        <source>Damaged: replays up to %1</source>
        <translation>Beschädigt: Wiedergabe bis %1</translation>
    </message>
    <message>
        <source>Previous marker (,)</source>
        <translation>Vorige Markierung (,)</translation>
    </message>
    <message>
        <source>Previous marker</source>
        <translation>Vorige Markierung</translation>
    </message>
    <message>
        <source>Next marker (.)</source>
        <translation>Nächste Markierung (.)</translation>
    </message>
    <message>
        <source>Next marker</source>
        <translation>Nächste Markierung</translation>
    </message>
</context>
<context>
    <name>RobotAddress</name>
    <message>
        <source>&apos;%1&apos; is not HOST:PORT with a port from 1 to 65535, e.g. raspberrypi:3333</source>
        <translation>„%1“ ist nicht HOST:PORT mit einem Port von 1 bis 65535, z. B. raspberrypi:3333</translation>
    </message>
    <message>
        <source>give only one of --sim, --port and --tcp</source>
        <translation>geben Sie nur eines von --sim, --port und --tcp an</translation>
    </message>
    <message>
        <source>give the serial port&apos;s path, e.g. /dev/ttyUSB0</source>
        <translation>geben Sie den Pfad der seriellen Schnittstelle an, z. B. /dev/ttyUSB0</translation>
    </message>
    <message>
        <source>unknown profile &apos;%1&apos; (roomba500, create2, create1 or auto)</source>
        <translation>unbekanntes Profil „%1“ (roomba500, create2, create1 oder auto)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a rate the robots know (300 to 115200)</source>
        <translation>„%1“ ist keine Baudrate, die die Roboter kennen (300 bis 115200)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not an option for where the robot is</source>
        <translation>„%1“ ist keine Angabe dazu, wo der Roboter ist</translation>
    </message>
    <message>
        <source>--profile, --baud and --brc-line go with --sim, --port or --tcp</source>
        <translation>--profile, --baud und --brc-line gehören zu --sim, --port oder --tcp</translation>
    </message>
    <message>
        <source>say where the robot is: --sim, --port PATH or --tcp HOST:PORT</source>
        <translation>sagen Sie, wo der Roboter ist: --sim, --port PFAD oder --tcp HOST:PORT</translation>
    </message>
</context>
<context>
    <name>RobotBar</name>
    <message>
        <source>Robots</source>
        <translation>Roboter</translation>
    </message>
    <message>
        <source>Recording of %1</source>
        <translation>Aufzeichnung eines %1</translation>
    </message>
    <message>
        <source>&amp;Stop all robots	Shift+Esc</source>
        <translation>Alle Roboter an&amp;halten	Umschalt+Esc</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>RobotCard</name>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>Robot %1</source>
        <translation>Roboter %1</translation>
    </message>
    <message>
        <source>%1, link %2</source>
        <translation>%1, Verbindung %2</translation>
    </message>
    <message>
        <source>%1
%2
Link: %3
Double-click to rename</source>
        <translation>%1
%2
Verbindung: %3
Doppelklick zum Umbenennen</translation>
    </message>
</context>
<context>
    <name>RobotDiagram</name>
    <message>
        <source>Robot sensor diagram</source>
        <translation>Sensordiagramm des Roboters</translation>
    </message>
    <message>
        <source>Data is stale</source>
        <translation>Daten sind veraltet</translation>
    </message>
    <message>
        <source>Bump left</source>
        <translation>Stoß links</translation>
    </message>
    <message>
        <source>Bump right</source>
        <translation>Stoß rechts</translation>
    </message>
    <message>
        <source>Wheel drop left</source>
        <translation>Radabsenkung links</translation>
    </message>
    <message>
        <source>Wheel drop right</source>
        <translation>Radabsenkung rechts</translation>
    </message>
    <message>
        <source>Caster wheel drop</source>
        <translation>Radabsenkung Stützrad</translation>
    </message>
    <message>
        <source>Cliff left</source>
        <translation>Abgrund links</translation>
    </message>
    <message>
        <source>Cliff front left</source>
        <translation>Abgrund vorne links</translation>
    </message>
    <message>
        <source>Cliff front right</source>
        <translation>Abgrund vorne rechts</translation>
    </message>
    <message>
        <source>Cliff right</source>
        <translation>Abgrund rechts</translation>
    </message>
    <message>
        <source>Wall</source>
        <translation>Wand</translation>
    </message>
    <message>
        <source>Light bumper %1</source>
        <translation>Lichtstoßfänger %1</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>No sensor data</source>
        <translation>Keine Sensordaten</translation>
    </message>
    <message>
        <source>Nothing detected</source>
        <translation>Nichts erkannt</translation>
    </message>
    <message>
        <source>; </source>
        <translation>; </translation>
    </message>
    <message>
        <source>Buttons</source>
        <translation>Tasten</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>Virtual wall</source>
        <translation>Virtuelle Wand</translation>
    </message>
    <message>
        <source>seen</source>
        <translation>erkannt</translation>
    </message>
    <message>
        <source>Overcurrent</source>
        <translation>Überstrom</translation>
    </message>
    <message>
        <source>IR</source>
        <translation>IR</translation>
    </message>
    <message>
        <source>Stasis</source>
        <translation>Stasis</translation>
    </message>
    <message>
        <source>not moving</source>
        <translation>steht</translation>
    </message>
    <message>
        <source>moving</source>
        <translation>fährt</translation>
    </message>
    <message>
        <source>DIRTY WHEEL</source>
        <translation>RAD VERSCHMUTZT</translation>
    </message>
    <message>
        <source>reserved (3)</source>
        <translation>reserviert (3)</translation>
    </message>
    <message>
        <source>IR omni</source>
        <translation>IR rundum</translation>
    </message>
    <message>
        <source>IR left</source>
        <translation>IR links</translation>
    </message>
    <message>
        <source>IR right</source>
        <translation>IR rechts</translation>
    </message>
    <message>
        <source>CARGO BAY</source>
        <translation>LADERAUM</translation>
    </message>
    <message>
        <source>DROP</source>
        <translation>UNTEN</translation>
    </message>
    <message>
        <source>WALL</source>
        <translation>WAND</translation>
    </message>
    <message>
        <source>STALE</source>
        <translation>VERALTET</translation>
    </message>
    <message>
        <source>The replay has ended</source>
        <translation>Die Wiedergabe ist zu Ende</translation>
    </message>
    <message>
        <source>ENDED</source>
        <translation>BEENDET</translation>
    </message>
</context>
<context>
    <name>RobotFirmware</name>
    <message>
        <source>The robot printed no firmware version within %1 s of Reset. Check that it is switched on and connected, and try again once it streams.</source>
        <translation>Der Roboter hat innerhalb von %1 s nach dem Reset keine Firmware-Version ausgegeben. Prüfen Sie, ob er eingeschaltet und verbunden ist, und versuchen Sie es erneut, sobald er Daten sendet.</translation>
    </message>
    <message>
        <source>The firmware version is not known: values are shown as the robot reports them.</source>
        <translation>Die Firmware-Version ist unbekannt: Die Werte werden so gezeigt, wie der Roboter sie meldet.</translation>
    </message>
    <message>
        <source>This firmware reports distance, angle and radius correctly: nothing needs correcting.</source>
        <translation>Diese Firmware meldet Strecke, Winkel und Radius richtig: Nichts muss korrigiert werden.</translation>
    </message>
    <message>
        <source>It reports the angle (packet 20) multiplied by %1: the angle is divided by %1 wherever it is shown, plotted, exported or used for the map.</source>
        <translation>Sie meldet den Winkel (Paket 20) mit %1 multipliziert: Der Winkel wird überall durch %1 geteilt, wo er gezeigt, geplottet, exportiert oder für die Karte genutzt wird.</translation>
    </message>
    <message>
        <source>It reports the distance (packet 19) and the requested radius (packet 40) wrongly: they are greyed, and the map uses the wheel encoders.</source>
        <translation>Sie meldet die Strecke (Paket 19) und den angeforderten Radius (Paket 40) falsch: Beide werden grau gezeigt, und die Karte nutzt die Radencoder.</translation>
    </message>
    <message>
        <source>This robot reports its mode (packet 35) one too high (Passive as 2, Safe as 3, Full as 4): the true mode is shown and used everywhere.</source>
        <translation>Dieser Roboter meldet seinen Modus (Paket 35) um eins zu hoch (Passive als 2, Safe als 3, Full als 4): Überall wird der wahre Modus gezeigt und verwendet.</translation>
    </message>
</context>
<context>
    <name>RobotFleet</name>
    <message>
        <source>Robot</source>
        <translation>Roboter</translation>
    </message>
</context>
<context>
    <name>RobotLink</name>
    <message>
        <source>%1: no transport for this kind of connection</source>
        <translation>%1: für diese Art Verbindung gibt es keinen Transport</translation>
    </message>
    <message>
        <source>%1: the connection ended during the check</source>
        <translation>%1: die Verbindung endete während der Prüfung</translation>
    </message>
    <message>
        <source>%1: switched off at its power button; press it or use Wake (roomba-ctl wake, or Connect again in the dashboard). The link streams again once it is on.</source>
        <translation>%1: an seiner Ein/Aus-Taste ausgeschaltet; drücken Sie sie oder nutzen Sie „Wecken“ (roomba-ctl wake oder erneut „Verbinden“ im Dashboard). Die Verbindung sendet wieder, sobald er eingeschaltet ist.</translation>
    </message>
    <message>
        <source>%1: the robot stopped sending and does not answer Start: is it still switched on, is its battery charged, and is the cable in?</source>
        <translation>%1: Der Roboter sendet nicht mehr und antwortet nicht auf Start: Ist er noch eingeschaltet, ist sein Akku geladen und steckt das Kabel?</translation>
    </message>
    <message>
        <source>%1: the robot stopped sending: it is probably asleep (a %2 sleeps after 5 minutes in Passive), and no pulse can wake it here: %3. Press Clean to wake it; the link streams again once it is awake. To wake it from here, wire its BRC pin to the adapter&apos;s RTS or DTR line and set that wake line.</source>
        <translation>%1: Der Roboter sendet nicht mehr: Er schläft wahrscheinlich (ein %2 schläft nach 5 Minuten in Passive), und hier kann ihn kein Impuls wecken: %3. Drücken Sie Clean, um ihn zu wecken; die Verbindung sendet wieder, sobald er wach ist. Um ihn von hier aus zu wecken, verbinden Sie seinen BRC-Pin mit der RTS- oder DTR-Leitung des Adapters und stellen Sie diese Weckleitung ein.</translation>
    </message>
    <message>
        <source>the port is closed</source>
        <translation>der Anschluss ist geschlossen</translation>
    </message>
    <message>
        <source>%1: the robot is asleep on its dock, and a BRC pulse did not wake it: firmware older than release-3.8.2 (release-stm32-3.7.7) is not woken by a pulse on the dock. Press Clean or lift it off the dock; the link streams again once it is awake.</source>
        <translation>%1: Der Roboter schläft auf seiner Ladestation, und ein BRC-Impuls hat ihn nicht geweckt: Firmware älter als release-3.8.2 (release-stm32-3.7.7) wacht auf der Station nicht durch einen Impuls auf. Drücken Sie Clean oder heben Sie ihn von der Station; die Verbindung sendet wieder, sobald er wach ist.</translation>
    </message>
    <message>
        <source>%1: the robot stopped sending and did not wake when its wake line (%2) was pulsed: it is asleep and the pulse does not reach it. The cable may carry the BRC pin on the other line (set the wake line to DTR, RTS or both; the connection check tries each) or not at all. On its dock, firmware older than release-3.8.2 is not woken by a pulse: press Clean or lift it off the dock; the link streams again once it is awake.</source>
        <translation>%1: Der Roboter sendet nicht mehr und ist nicht aufgewacht, als seine Weckleitung (%2) gepulst wurde: Er schläft, und der Impuls erreicht ihn nicht. Vielleicht führt das Kabel den BRC-Pin auf der anderen Leitung (stellen Sie die Weckleitung auf DTR, RTS oder beide; die Verbindungsprüfung probiert jede) oder gar nicht. Auf der Ladestation wacht Firmware älter als release-3.8.2 nicht durch einen Impuls auf: Drücken Sie Clean oder heben Sie ihn von der Station; die Verbindung sendet wieder, sobald er wach ist.</translation>
    </message>
    <message>
        <source>%1: no data: is the robot on, and is the baud right?</source>
        <translation>%1: keine Daten: Ist der Roboter eingeschaltet und stimmt die Baudrate?</translation>
    </message>
    <message>
        <source>(If it is asleep: %1.)</source>
        <translation>(Falls er schläft: %1.)</translation>
    </message>
    <message>
        <source>no packet fits in a 15 ms frame at %1 baud</source>
        <translation>bei %1 Baud passt kein Paket in einen 15-ms-Frame</translation>
    </message>
    <message>
        <source>%1: cannot stream: %2</source>
        <translation>%1: Datenstrom nicht möglich: %2</translation>
    </message>
    <message>
        <source>not connected: the command was not sent</source>
        <translation>nicht verbunden: der Befehl wurde nicht gesendet</translation>
    </message>
    <message>
        <source>the connection check is running: the command was not sent</source>
        <translation>die Verbindungsprüfung läuft: der Befehl wurde nicht gesendet</translation>
    </message>
    <message>
        <source>%1: Reset put the robot back at its default %2 baud, which this connection cannot follow from %3: %4</source>
        <translation>%1: Reset hat den Roboter auf seine Standardrate von %2 Baud zurückgesetzt, der diese Verbindung von %3 aus nicht folgen kann: %4</translation>
    </message>
    <message>
        <source>%1: Reset put the robot back at its default %2 baud: the port now talks at %2 too (it was %3).</source>
        <translation>%1: Reset hat den Roboter auf seine Standardrate von %2 Baud zurückgesetzt: Der Anschluss spricht jetzt ebenfalls mit %2 (vorher %3).</translation>
    </message>
    <message>
        <source>Not sent: %1</source>
        <translation>Nicht gesendet: %1</translation>
    </message>
    <message>
        <source>%1: write failed</source>
        <translation>%1: Schreiben fehlgeschlagen</translation>
    </message>
    <message>
        <source>not connected: the sensor query was not sent</source>
        <translation>nicht verbunden: die Sensorabfrage wurde nicht gesendet</translation>
    </message>
    <message>
        <source>sensor query: %1 is not a packet or group of the %2</source>
        <translation>Sensorabfrage: %1 ist kein Paket und keine Gruppe des %2</translation>
    </message>
    <message>
        <source>sensor query: ask for 1 to 255 packets</source>
        <translation>Sensorabfrage: 1 bis 255 Pakete anfordern</translation>
    </message>
    <message>
        <source>sensor query: the %1 has no Query List; ask for one group at a time (0 is every packet)</source>
        <translation>Sensorabfrage: der %1 kennt kein Query List; fordern Sie jeweils eine Gruppe an (0 sind alle Pakete)</translation>
    </message>
    <message>
        <source>not connected: Show Script was not sent</source>
        <translation>nicht verbunden: Show Script wurde nicht gesendet</translation>
    </message>
    <message>
        <source>the %1 has no scripts</source>
        <translation>der %1 hat keine Skripte</translation>
    </message>
    <message>
        <source>%1: the stream did not pause; the sensor query was not sent</source>
        <translation>%1: der Datenstrom hielt nicht an; die Sensorabfrage wurde nicht gesendet</translation>
    </message>
    <message>
        <source>%1: no reply to Show Script</source>
        <translation>%1: keine Antwort auf Show Script</translation>
    </message>
    <message>
        <source>%1: no reply to the sensor query</source>
        <translation>%1: keine Antwort auf die Sensorabfrage</translation>
    </message>
    <message>
        <source>not connected: there is nothing to wake</source>
        <translation>nicht verbunden: es gibt nichts zu wecken</translation>
    </message>
    <message>
        <source>%1: no pulse can wake the robot here: %2. Press its power button (Clean).</source>
        <translation>%1: hier kann kein Impuls den Roboter wecken: %2. Drücken Sie seine Ein/Aus-Taste (Clean).</translation>
    </message>
    <message>
        <source>not connected: there is nothing to check</source>
        <translation>nicht verbunden: es gibt nichts zu prüfen</translation>
    </message>
    <message>
        <source>%1: the port is not open yet</source>
        <translation>%1: der Anschluss ist noch nicht geöffnet</translation>
    </message>
</context>
<context>
    <name>RobotList</name>
    <message>
        <source>Add robot</source>
        <translation>Roboter hinzufügen</translation>
    </message>
    <message>
        <source>Add a robot to the window: a virtual one, a serial port or TCP bridge, or a recording</source>
        <translation>Einen Roboter zum Fenster hinzufügen: einen virtuellen, einen seriellen Port oder eine TCP-Brücke, oder eine Aufzeichnung</translation>
    </message>
    <message>
        <source>Virtual robot</source>
        <translation>Virtueller Roboter</translation>
    </message>
    <message>
        <source>Serial port or TCP bridge…</source>
        <translation>Serieller Port oder TCP-Brücke…</translation>
    </message>
    <message>
        <source>Recording…</source>
        <translation>Aufzeichnung…</translation>
    </message>
    <message>
        <source>Rename</source>
        <translation>Umbenennen</translation>
    </message>
    <message>
        <source>Rename the selected robot (or double-click its card)</source>
        <translation>Den ausgewählten Roboter umbenennen (oder seine Karte doppelklicken)</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Stop the selected robot, leave it in Passive and remove it from the window</source>
        <translation>Den ausgewählten Roboter anhalten, in Passiv lassen und aus dem Fenster entfernen</translation>
    </message>
    <message>
        <source>Robot name</source>
        <translation>Name des Roboters</translation>
    </message>
</context>
<context>
    <name>RobotMarkers</name>
    <message>
        <source>Markers are kept in a recording: start one (File → Record) or open one.</source>
        <translation>Markierungen werden in einer Aufzeichnung gespeichert: Starten Sie eine (Datei → Aufzeichnen) oder öffnen Sie eine.</translation>
    </message>
    <message>
        <source>There is no marker %1.</source>
        <translation>Es gibt keine Markierung %1.</translation>
    </message>
    <message>
        <source>The marker could not be saved: %1</source>
        <translation>Die Markierung konnte nicht gespeichert werden: %1</translation>
    </message>
    <message>
        <source>A recording holds at most %1 markers.</source>
        <translation>Eine Aufzeichnung fasst höchstens %1 Markierungen.</translation>
    </message>
</context>
<context>
    <name>RobotMode</name>
    <message>
        <source>left</source>
        <translation>links</translation>
    </message>
    <message>
        <source>front left</source>
        <translation>vorne links</translation>
    </message>
    <message>
        <source>front right</source>
        <translation>vorne rechts</translation>
    </message>
    <message>
        <source>right</source>
        <translation>rechts</translation>
    </message>
    <message>
        <source>cliff (%1)</source>
        <translation>Abgrund (%1)</translation>
    </message>
    <message>
        <source>, </source>
        <translation>, </translation>
    </message>
    <message>
        <source>caster</source>
        <translation>Stützrad</translation>
    </message>
    <message>
        <source>wheel drop (%1)</source>
        <translation>Rad abgesenkt (%1)</translation>
    </message>
    <message>
        <source>charger</source>
        <translation>Ladegerät</translation>
    </message>
    <message>
        <source> and </source>
        <translation> und </translation>
    </message>
    <message>
        <source>You asked for Passive at %1.</source>
        <translation>Um %1 auf Ihren Wunsch in Passive gewechselt.</translation>
    </message>
    <message>
        <source>A safety stop dropped it to Passive at %1.</source>
        <translation>Um %1 durch einen Sicherheitsstopp in Passive gefallen.</translation>
    </message>
    <message>
        <source>A %1 dropped it to Passive at %2.</source>
        <translation>Um %2 in Passive gefallen: %1.</translation>
    </message>
    <message>
        <source>asked for</source>
        <translation>gewünscht</translation>
    </message>
    <message>
        <source>safety stop</source>
        <translation>Sicherheitsstopp</translation>
    </message>
    <message>
        <source>Carry it back from the edge, then Enter Safe.</source>
        <translation>Tragen Sie ihn von der Kante weg, dann Safe aktivieren.</translation>
    </message>
    <message>
        <source>Put it back on its wheels, then Enter Safe.</source>
        <translation>Stellen Sie ihn wieder auf die Räder, dann Safe aktivieren.</translation>
    </message>
    <message>
        <source>Enter Safe to drive.</source>
        <translation>Zum Fahren Safe aktivieren.</translation>
    </message>
    <message>
        <source>%1 needs Safe or Full mode: in Passive the Create ignores the script&apos;s Drive, so a wait never ends. Enter Safe first.</source>
        <translation>%1 braucht den Modus Safe oder Full: in Passive überhört der Create das Drive des Skripts, sodass ein Warten nie endet. Zuerst Safe aktivieren.</translation>
    </message>
    <message>
        <source>%1 needs Safe or Full mode: the robot ignores it in Passive. Enter Safe first.</source>
        <translation>%1 braucht den Modus Safe oder Full: in Passive überhört der Roboter den Befehl. Zuerst Safe aktivieren.</translation>
    </message>
    <message>
        <source>Out of reach: %1 The goal needs the %2 cliff sensor to reach the edge first. Carry the robot back from the edge, Enter Safe, and drive at the edge head on.</source>
        <translation>Nicht erreichbar: %1 Für das Ziel muss zuerst der Abgrundsensor %2 die Kante erreichen. Tragen Sie den Roboter von der Kante weg, aktivieren Sie Safe und fahren Sie gerade auf die Kante zu.</translation>
    </message>
    <message>
        <source> or </source>
        <translation> oder </translation>
    </message>
    <message>
        <source>Out of reach: the robot does not drive in Passive mode. %1</source>
        <translation>Nicht erreichbar: Im Modus Passive fährt der Roboter nicht. %1</translation>
    </message>
    <message>
        <source>on the dock, not charging</source>
        <translation>auf der Ladestation, lädt nicht</translation>
    </message>
    <message>
        <source>Full mode on the dock: the battery does not charge, it drains.</source>
        <translation>Full-Modus auf der Ladestation: der Akku lädt nicht, er entlädt sich.</translation>
    </message>
    <message>
        <source>Safe mode on the dock: the battery does not charge, it drains.</source>
        <translation>Safe-Modus auf der Ladestation: der Akku lädt nicht, er entlädt sich.</translation>
    </message>
    <message>
        <source>The robot is on its dock: Safe mode is refused on the charger (%1).</source>
        <translation>Der Roboter steht auf seiner Ladestation: am Ladegerät wird der Safe-Modus verweigert (%1).</translation>
    </message>
    <message>
        <source>Safe refused on the dock</source>
        <translation>Safe auf der Ladestation verweigert</translation>
    </message>
    <message>
        <source>Enter Passive to charge it, or drive it off the dock.</source>
        <translation>Passive einschalten, damit er lädt, oder ihn von der Ladestation fahren.</translation>
    </message>
    <message>
        <source>Lift it off the dock, or drive it off in Full (Full does not stop at cliffs or wheel drops).</source>
        <translation>Heben Sie ihn von der Ladestation, oder fahren Sie ihn im Full-Modus herunter (Full hält nicht an Abgründen oder abgesenkten Rädern).</translation>
    </message>
    <message>
        <source>Carry it back from the edge, then Enter Safe. Its cliff signals read %1 of 4095, as over a dark rug: if you can see the floor under it, carry it to a lighter floor, then Enter Safe.</source>
        <translation>Tragen Sie ihn von der Kante weg, dann Safe aktivieren. Seine Abgrundsignale lesen %1 von 4095, wie über einem dunklen Teppich: Sehen Sie den Boden unter ihm, tragen Sie ihn auf einen helleren Boden, dann Safe aktivieren.</translation>
    </message>
    <message>
        <source>Cleaning (its own program) · Space stops it</source>
        <translation>Reinigt (sein eigenes Programm) · Leertaste hält ihn an</translation>
    </message>
    <message>
        <source>Seeking its dock (its own program) · Space stops it</source>
        <translation>Sucht seine Ladestation (sein eigenes Programm) · Leertaste hält ihn an</translation>
    </message>
    <message>
        <source>Running a demo (its own program) · Space stops it</source>
        <translation>Führt eine Demo aus (sein eigenes Programm) · Leertaste hält ihn an</translation>
    </message>
    <message>
        <source>cleaning</source>
        <translation>reinigt</translation>
    </message>
    <message>
        <source>seeking its dock</source>
        <translation>sucht die Ladestation</translation>
    </message>
    <message>
        <source>running a demo</source>
        <translation>führt eine Demo aus</translation>
    </message>
    <message>
        <source>the robot is off the floor: Full mode would drive its wheels in your hands</source>
        <translation>der Roboter steht nicht auf dem Boden: Im Full-Modus würden sich seine Räder in Ihren Händen drehen</translation>
    </message>
    <message>
        <source>battery nearly flat</source>
        <translation>Akku fast leer</translation>
    </message>
    <message>
        <source>%1 (it fell to Passive at %2).</source>
        <translation>%1 (um %2 in Passive gefallen).</translation>
    </message>
    <message>
        <source>Put it on its dock in Passive to charge it; it drives again once charged.</source>
        <translation>Stellen Sie ihn in Passive auf seine Ladestation, damit er lädt; geladen fährt er wieder.</translation>
    </message>
</context>
<context>
    <name>RobotSession</name>
    <message>
        <source>Connect to the robot first: its firmware version is read from the robot.</source>
        <translation>Verbinden Sie sich zuerst mit dem Roboter: Die Firmware-Version wird vom Roboter gelesen.</translation>
    </message>
    <message>
        <source>A recording cannot be reset: connect to the robot itself to read its firmware version.</source>
        <translation>Eine Aufzeichnung lässt sich nicht zurücksetzen: Verbinden Sie sich mit dem Roboter selbst, um seine Firmware-Version zu lesen.</translation>
    </message>
    <message>
        <source>A robot on the broker is reset only by its bridge: read its firmware version where the bridge runs.</source>
        <translation>Ein Roboter am Broker wird nur von seiner Bridge zurückgesetzt: Lesen Sie seine Firmware-Version dort, wo die Bridge läuft.</translation>
    </message>
    <message>
        <source>Not sent: %1</source>
        <translation>Nicht gesendet: %1</translation>
    </message>
    <message>
        <source>This robot reports its mode one too high (Passive as Safe, as some Wi-Fi Roomba 600s do): the true mode is shown from now on, and remembered for this robot.</source>
        <translation>Dieser Roboter meldet seinen Modus um eins zu hoch (Passive als Safe, wie manche WLAN-Roomba-600): Ab jetzt wird der wahre Modus gezeigt und für diesen Roboter gemerkt.</translation>
    </message>
    <message>
        <source>Not sent: %1. Put it down on the floor first.</source>
        <translation>Nicht gesendet: %1. Stellen Sie ihn zuerst auf den Boden.</translation>
    </message>
    <message>
        <source>Motion sent with the %1.</source>
        <translation>Fahrbefehl gesendet, aber: %1.</translation>
    </message>
    <message>
        <source>Motion stopped: %1. Put it down on the floor first.</source>
        <translation>Fahrt angehalten: %1. Stellen Sie ihn zuerst auf den Boden.</translation>
    </message>
    <message>
        <source>The charge fell from %1 % to %2 % as the robot guessed it again from its voltage at boot. A pack that reads full on the charger and much lower under load is worn: see Battery in the gauges.</source>
        <translation>Die Ladung fiel von %1 % auf %2 %, als der Roboter sie beim Start erneut aus seiner Spannung schätzte. Ein Akku, der am Ladegerät voll anzeigt und unter Last viel weniger, ist verschlissen: siehe Akku in den Messanzeigen.</translation>
    </message>
</context>
<context>
    <name>RobotStatusBar</name>
    <message>
        <source>closed</source>
        <translation>geschlossen</translation>
    </message>
    <message>
        <source>connecting</source>
        <translation>verbindet</translation>
    </message>
    <message>
        <source>streaming</source>
        <translation>Datenstrom läuft</translation>
    </message>
    <message>
        <source>stale</source>
        <translation>veraltet</translation>
    </message>
    <message>
        <source>lost</source>
        <translation>verloren</translation>
    </message>
    <message>
        <source>reconnecting</source>
        <translation>verbindet neu</translation>
    </message>
    <message>
        <source>Link: %1</source>
        <translation>Verbindung: %1</translation>
    </message>
    <message>
        <source>%1 frames/s</source>
        <translation>%1 Frames/s</translation>
    </message>
    <message>
        <source>checksum failures %1, resyncs %2</source>
        <translation>Prüfsummenfehler %1, Neusynchronisierungen %2</translation>
    </message>
    <message>
        <source>Firmware %1</source>
        <translation>Firmware %1</translation>
    </message>
    <message>
        <source>● REC %1 kB %2</source>
        <translation>● REC %1 kB %2</translation>
    </message>
    <message>
        <source>  REPLAY, NOT LIVE  </source>
        <translation>  WIEDERGABE, NICHT LIVE  </translation>
    </message>
    <message>
        <source>  NO LIVE DATA  </source>
        <translation>  KEINE LIVE-DATEN  </translation>
    </message>
    <message>
        <source>%1 messages/s from the bridge</source>
        <translation>%1 Nachrichten/s von der Bridge</translation>
    </message>
    <message>
        <source>Telemetry messages from the robot&apos;s bridge, which sends only what changed. The robot&apos;s own frame rate is on its tile in the fleet view.</source>
        <translation>Telemetrienachrichten der Bridge des Roboters, die nur Änderungen sendet. Die eigene Bildrate des Roboters steht auf seiner Kachel in der Flottenansicht.</translation>
    </message>
    <message>
        <source>Roomba 500 or Create 2? (not yet identified)</source>
        <translation>Roomba 500 oder Create 2? (noch nicht erkannt)</translation>
    </message>
    <message>
        <source>Recording saved: %1</source>
        <translation>Aufzeichnung gespeichert: %1</translation>
    </message>
    <message>
        <source>  REPLAY FINISHED  </source>
        <translation>  WIEDERGABE BEENDET  </translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>nicht verbunden</translation>
    </message>
    <message>
        <source>replay finished</source>
        <translation>Wiedergabe beendet</translation>
    </message>
    <message>
        <source>replaying</source>
        <translation>Wiedergabe läuft</translation>
    </message>
    <message>
        <source>replay paused</source>
        <translation>Wiedergabe angehalten</translation>
    </message>
    <message>
        <source>Link: replay finished</source>
        <translation>Verbindung: Wiedergabe beendet</translation>
    </message>
    <message>
        <source>Link: replaying a recording</source>
        <translation>Verbindung: Wiedergabe einer Aufzeichnung</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
</context>
<context>
    <name>RoomActions</name>
    <message>
        <source>Classroom</source>
        <translation>Klassenzimmer</translation>
    </message>
    <message>
        <source>Empty floor</source>
        <translation>Leerer Boden</translation>
    </message>
    <message>
        <source>Table top</source>
        <translation>Tischplatte</translation>
    </message>
    <message>
        <source>Corridor</source>
        <translation>Flur</translation>
    </message>
    <message>
        <source>Dock corner</source>
        <translation>Ecke mit Ladestation</translation>
    </message>
    <message>
        <source>O&amp;pen room…</source>
        <translation>&amp;Raum öffnen…</translation>
    </message>
    <message>
        <source>Put the virtual robots in a room from a file</source>
        <translation>Die virtuellen Roboter in einen Raum aus einer Datei stellen</translation>
    </message>
    <message>
        <source>Sa&amp;ve room as…</source>
        <translation>Raum speichern &amp;unter…</translation>
    </message>
    <message>
        <source>Write the virtual robots&apos; room, as edited on the map, to a file</source>
        <translation>Den Raum der virtuellen Roboter, wie er auf der Karte bearbeitet wurde, in eine Datei schreiben</translation>
    </message>
    <message>
        <source>E&amp;xample rooms</source>
        <translation>Bei&amp;spielräume</translation>
    </message>
    <message>
        <source>&amp;Undo room edit</source>
        <translation>Raumänderung &amp;rückgängig</translation>
    </message>
    <message>
        <source>Re&amp;do room edit</source>
        <translation>Raumänderung &amp;wiederholen</translation>
    </message>
    <message>
        <source>The room of last time could not be opened: %1</source>
        <translation>Der Raum vom letzten Mal konnte nicht geöffnet werden: %1</translation>
    </message>
    <message>
        <source>Room opened: %1</source>
        <translation>Raum geöffnet: %1</translation>
    </message>
    <message>
        <source>Open room</source>
        <translation>Raum öffnen</translation>
    </message>
    <message>
        <source>This room could not be opened; the room stays as it was.

%1</source>
        <translation>Dieser Raum konnte nicht geöffnet werden; der Raum bleibt, wie er war.

%1</translation>
    </message>
    <message>
        <source>Rooms (*.json);;All files (*)</source>
        <translation>Räume (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Save room as</source>
        <translation>Raum speichern unter</translation>
    </message>
    <message>
        <source>Room saved to %1</source>
        <translation>Raum gespeichert in %1</translation>
    </message>
    <message>
        <source>The room could not be saved.

%1</source>
        <translation>Der Raum konnte nicht gespeichert werden.

%1</translation>
    </message>
</context>
<context>
    <name>RoomEditTool</name>
    <message>
        <source>Edit room</source>
        <translation>Raum bearbeiten</translation>
    </message>
    <message>
        <source>Add wall here</source>
        <translation>Wand hier hinzufügen</translation>
    </message>
    <message>
        <source>Add stage edge here</source>
        <translation>Bühnenkante hier hinzufügen</translation>
    </message>
    <message>
        <source>Move the virtual wall here</source>
        <translation>Virtuelle Wand hierher versetzen</translation>
    </message>
    <message>
        <source>Add virtual wall here</source>
        <translation>Virtuelle Wand hier hinzufügen</translation>
    </message>
    <message>
        <source>Put the dock here</source>
        <translation>Ladestation hierher stellen</translation>
    </message>
    <message>
        <source>Delete %1</source>
        <translation>Löschen: %1</translation>
    </message>
    <message>
        <source>Editing %1: drag it or its handles · Delete removes it</source>
        <translation>Bearbeiten: %1 · ziehen, auch an den Griffen · Entf löscht</translation>
    </message>
    <message>
        <source>Editing the room: click a thing to select it · right-click to add</source>
        <translation>Raum bearbeiten: zum Auswählen anklicken · Rechtsklick fügt hinzu</translation>
    </message>
    <message>
        <source>the wall</source>
        <translation>die Wand</translation>
    </message>
    <message>
        <source>the stage edge</source>
        <translation>die Bühnenkante</translation>
    </message>
    <message>
        <source>the dock</source>
        <translation>die Ladestation</translation>
    </message>
    <message>
        <source>the virtual wall</source>
        <translation>die virtuelle Wand</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>%1 × %2 m</source>
        <translation>%1 × %2 m</translation>
    </message>
</context>
<context>
    <name>RoomFile</name>
    <message>
        <source>&quot;format&quot; must be &quot;%1&quot;</source>
        <translation>&quot;format&quot; muss &quot;%1&quot; sein</translation>
    </message>
    <message>
        <source>&quot;version&quot; %1 is not one this program reads (it reads %2)</source>
        <translation>&quot;version&quot; %1 kann dieses Programm nicht lesen (es liest %2)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be a list</source>
        <translation>&quot;%1&quot; muss eine Liste sein</translation>
    </message>
    <message>
        <source>%1: a wall must have some length</source>
        <translation>%1: eine Wand muss eine Länge haben</translation>
    </message>
    <message>
        <source>%1: x_min must be below x_max and y_min below y_max</source>
        <translation>%1: x_min muss kleiner als x_max und y_min kleiner als y_max sein</translation>
    </message>
    <message>
        <source>virtual_wall: &quot;range_mm&quot; must be above 0, not %1</source>
        <translation>virtual_wall: &quot;range_mm&quot; muss größer als 0 sein, nicht %1</translation>
    </message>
    <message>
        <source>unknown key &quot;%1&quot;</source>
        <translation>unbekannter Schlüssel &quot;%1&quot;</translation>
    </message>
    <message>
        <source>%1: unknown key &quot;%2&quot;</source>
        <translation>%1: unbekannter Schlüssel &quot;%2&quot;</translation>
    </message>
    <message>
        <source>%1 must be a number</source>
        <translation>%1 muss eine Zahl sein</translation>
    </message>
    <message>
        <source>%1 must be a list of %2 numbers</source>
        <translation>%1 muss eine Liste mit %2 Zahlen sein</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be an object with x_mm, y_mm and heading_deg</source>
        <translation>&quot;%1&quot; muss ein Objekt mit x_mm, y_mm und heading_deg sein</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is missing</source>
        <translation>%1: &quot;%2&quot; fehlt</translation>
    </message>
    <message>
        <source>line %1, column %2</source>
        <translation>Zeile %1, Spalte %2</translation>
    </message>
    <message>
        <source>not JSON at %1: %2</source>
        <translation>kein JSON in %1: %2</translation>
    </message>
    <message>
        <source>a room file holds one JSON object</source>
        <translation>eine Raumdatei enthält ein JSON-Objekt</translation>
    </message>
    <message>
        <source>%1: cannot read: %2</source>
        <translation>%1: nicht lesbar: %2</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1: cannot write: %2</source>
        <translation>%1: nicht schreibbar: %2</translation>
    </message>
    <message>
        <source>%1: the shade (the fifth number) must be from 0 (the floor as it is) to 1 (black), not %2</source>
        <translation>%1: der Farbton (die fünfte Zahl) muss zwischen 0 (der Boden, wie er ist) und 1 (schwarz) liegen, nicht %2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; has %2 entries; a room holds at most %3</source>
        <translation>&quot;%1&quot; hat %2 Einträge; ein Raum fasst höchstens %3</translation>
    </message>
</context>
<context>
    <name>RtttlImport</name>
    <message>
        <source>RTTTL: %1</source>
        <translation>RTTTL: %1</translation>
    </message>
    <message>
        <source>expected NAME:DEFAULTS:NOTES, e.g. &quot;Beep:d=4,o=5,b=120:c,e,g&quot;</source>
        <translation>erwartet NAME:VORGABEN:NOTEN, z. B. „Beep:d=4,o=5,b=120:c,e,g“</translation>
    </message>
    <message>
        <source>default &quot;%1&quot; is not KEY=NUMBER</source>
        <translation>Vorgabe „%1“ hat nicht die Form SCHLÜSSEL=ZAHL</translation>
    </message>
    <message>
        <source>default &quot;%1&quot; is not valid (d: 1..32, o: 4..7, b: 1..900)</source>
        <translation>Vorgabe „%1“ ist ungültig (d: 1..32, o: 4..7, b: 1..900)</translation>
    </message>
    <message>
        <source>the tune has no notes</source>
        <translation>die Melodie enthält keine Noten</translation>
    </message>
    <message>
        <source>note %1 &quot;%2&quot;: %3</source>
        <translation>Note %1 „%2“: %3</translation>
    </message>
    <message>
        <source>duration must be 1, 2, 4, 8, 16 or 32</source>
        <translation>Dauer muss 1, 2, 4, 8, 16 oder 32 sein</translation>
    </message>
    <message>
        <source>no note letter</source>
        <translation>kein Notenbuchstabe</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a note (a..g, h) or pause (p)</source>
        <translation>„%1“ ist weder Note (a..g, h) noch Pause (p)</translation>
    </message>
    <message>
        <source>octave must be 4..7</source>
        <translation>Oktave muss 4..7 sein</translation>
    </message>
    <message>
        <source>unexpected &quot;%1&quot;</source>
        <translation>unerwartetes „%1“</translation>
    </message>
    <message>
        <source>lasts %1/64 s at %2 beats per minute; a note lasts 1..255</source>
        <translation>dauert %1/64 s bei %2 Schlägen pro Minute; eine Note dauert 1..255</translation>
    </message>
</context>
<context>
    <name>RunComparison</name>
    <message>
        <source>Show a second recording beside this run: plots and map, in a style of its own</source>
        <translation>Eine zweite Aufzeichnung neben dieser Fahrt zeigen: Diagramme und Karte, in einem eigenen Stil</translation>
    </message>
    <message>
        <source>Comparison</source>
        <translation>Vergleich</translation>
    </message>
    <message>
        <source>Compare with recording</source>
        <translation>Mit Aufzeichnung vergleichen</translation>
    </message>
    <message>
        <source>Roomba Dashboard recordings (*.oirec);;All files (*)</source>
        <translation>Roomba-Dashboard-Aufzeichnungen (*.oirec);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>This file cannot be compared.

%1</source>
        <translation>Diese Datei kann nicht verglichen werden.

%1</translation>
    </message>
    <message>
        <source>&amp;Compare with recording…</source>
        <translation>Mit Aufzeichnung ver&amp;gleichen…</translation>
    </message>
    <message>
        <source>C&amp;lose comparison</source>
        <translation>Vergleich sch&amp;ließen</translation>
    </message>
</context>
<context>
    <name>RxFrameScanner</name>
    <message>
        <source>text &quot;%1&quot;</source>
        <translation>Text „%1“</translation>
    </message>
    <message>
        <source>outside any stream frame</source>
        <translation>außerhalb eines Datenstrom-Frames</translation>
    </message>
    <message>
        <source>stream frame: %1</source>
        <translation>Datenstrom-Frame: %1</translation>
    </message>
    <message>
        <source>reply: %1</source>
        <translation>Antwort: %1</translation>
    </message>
</context>
<context>
    <name>ScheduleEditor</name>
    <message>
        <source>Sunday</source>
        <translation>Sonntag</translation>
    </message>
    <message>
        <source>Monday</source>
        <translation>Montag</translation>
    </message>
    <message>
        <source>Tuesday</source>
        <translation>Dienstag</translation>
    </message>
    <message>
        <source>Wednesday</source>
        <translation>Mittwoch</translation>
    </message>
    <message>
        <source>Thursday</source>
        <translation>Donnerstag</translation>
    </message>
    <message>
        <source>Friday</source>
        <translation>Freitag</translation>
    </message>
    <message>
        <source>Saturday</source>
        <translation>Samstag</translation>
    </message>
    <message>
        <source>Weekly cleaning schedule (167)</source>
        <translation>Wöchentlicher Reinigungsplan (167)</translation>
    </message>
    <message>
        <source>Cleaning time on %1</source>
        <translation>Reinigungszeit am %1</translation>
    </message>
    <message>
        <source>Send Schedule</source>
        <translation>Zeitplan senden</translation>
    </message>
    <message>
        <source>Disable all</source>
        <translation>Alle deaktivieren</translation>
    </message>
    <message>
        <source>Clear every day and send a schedule with no cleaning</source>
        <translation>Alle Tage leeren und einen Zeitplan ohne Reinigung senden</translation>
    </message>
    <message>
        <source>Nothing sent yet. The robot cannot report its schedule, so this shows what was last sent from here.</source>
        <translation>Noch nichts gesendet. Der Roboter kann seinen Zeitplan nicht melden; hier steht daher, was zuletzt von hier gesendet wurde.</translation>
    </message>
    <message>
        <source>Last sent: %1 at %2</source>
        <translation>Zuletzt gesendet: %1 um %2</translation>
    </message>
    <message>
        <source>Presets</source>
        <translation>Vorlagen</translation>
    </message>
    <message>
        <source>Saved presets</source>
        <translation>Gespeicherte Vorlagen</translation>
    </message>
    <message>
        <source>Load</source>
        <translation>Laden</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <source>Preset name</source>
        <translation>Vorlagenname</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Speichern</translation>
    </message>
    <message>
        <source>Save the grid under this name</source>
        <translation>Raster unter diesem Namen speichern</translation>
    </message>
    <message>
        <source>Robot clock (168)</source>
        <translation>Roboteruhr (168)</translation>
    </message>
    <message>
        <source>Set from this computer&apos;s clock</source>
        <translation>Von der Uhr dieses Computers übernehmen</translation>
    </message>
    <message>
        <source>Day for the robot clock</source>
        <translation>Tag für die Roboteruhr</translation>
    </message>
    <message>
        <source>Time for the robot clock</source>
        <translation>Uhrzeit für die Roboteruhr</translation>
    </message>
    <message>
        <source>Set Day/Time</source>
        <translation>Tag/Uhrzeit setzen</translation>
    </message>
    <message>
        <source>The %1 has no cleaning schedule or clock: Schedule (167) and Set Day/Time (168) are Roomba 500 / Create 2 only.</source>
        <translation>Der %1 hat keinen Reinigungsplan und keine Uhr: Schedule (167) und Set Day/Time (168) gibt es nur bei Roomba 500 / Create 2.</translation>
    </message>
    <message>
        <source>Will send: %1</source>
        <translation>Wird gesendet: %1</translation>
    </message>
    <message>
        <source>Not sent: %1</source>
        <translation>Nicht gesendet: %1</translation>
    </message>
    <message>
        <source>Sent: no scheduled cleaning.</source>
        <translation>Gesendet: keine geplante Reinigung.</translation>
    </message>
    <message>
        <source>Schedule sent.</source>
        <translation>Zeitplan gesendet.</translation>
    </message>
    <message>
        <source>Robot clock set to %1 %2.</source>
        <translation>Roboteruhr auf %1 %2 gestellt.</translation>
    </message>
    <message>
        <source>Not saved: give the preset a name.</source>
        <translation>Nicht gespeichert: Geben Sie der Vorlage einen Namen.</translation>
    </message>
    <message>
        <source>Preset &quot;%1&quot; replaced.</source>
        <translation>Vorlage „%1“ ersetzt.</translation>
    </message>
    <message>
        <source>Preset &quot;%1&quot; saved.</source>
        <translation>Vorlage „%1“ gespeichert.</translation>
    </message>
    <message>
        <source>No preset named &quot;%1&quot;.</source>
        <translation>Keine Vorlage namens „%1“.</translation>
    </message>
    <message>
        <source>Preset &quot;%1&quot; is damaged: %2</source>
        <translation>Vorlage „%1“ ist beschädigt: %2</translation>
    </message>
    <message>
        <source>Preset &quot;%1&quot; loaded; press Send Schedule to send it.</source>
        <translation>Vorlage „%1“ geladen; zum Senden auf „Zeitplan senden“ klicken.</translation>
    </message>
    <message>
        <source>Preset &quot;%1&quot; deleted.</source>
        <translation>Vorlage „%1“ gelöscht.</translation>
    </message>
</context>
<context>
    <name>ScriptEditor</name>
    <message>
        <source>Drive 40 cm and stop</source>
        <translation>40 cm fahren und anhalten</translation>
    </message>
    <message>
        <source>Toggle LED on bump</source>
        <translation>LED bei Stoß umschalten</translation>
    </message>
    <message>
        <source>Drive in a square</source>
        <translation>Im Quadrat fahren</translation>
    </message>
    <message>
        <source>Load an example…</source>
        <translation>Beispiel laden…</translation>
    </message>
    <message>
        <source>Example scripts</source>
        <translation>Beispielskripte</translation>
    </message>
    <message>
        <source>One command a line, e.g.
%1</source>
        <translation>Ein Befehl pro Zeile, z. B.
%1</translation>
    </message>
    <message>
        <source>Script</source>
        <translation>Skript</translation>
    </message>
    <message>
        <source>Upload (152)</source>
        <translation>Hochladen (152)</translation>
    </message>
    <message>
        <source>Play (153)</source>
        <translation>Abspielen (153)</translation>
    </message>
    <message>
        <source>Run the stored script</source>
        <translation>Gespeichertes Skript ausführen</translation>
    </message>
    <message>
        <source>Show Script (154)</source>
        <translation>Skript anzeigen (154)</translation>
    </message>
    <message>
        <source>Read the stored script back and compare it with what was uploaded</source>
        <translation>Gespeichertes Skript zurücklesen und mit dem Hochgeladenen vergleichen</translation>
    </message>
    <message>
        <source>Demos (136)</source>
        <translation>Demos (136)</translation>
    </message>
    <message>
        <source>%1  %2</source>
        <translation>%1  %2</translation>
    </message>
    <message>
        <source>Scripts and demos are for the original Create only: %1.</source>
        <translation>Skripte und Demos gibt es nur beim ursprünglichen Create: %1.</translation>
    </message>
    <message>
        <source>? / %1 bytes</source>
        <translation>? / %1 Bytes</translation>
    </message>
    <message>
        <source>0 / %1 bytes</source>
        <translation>0 / %1 Bytes</translation>
    </message>
    <message>
        <source>Line %1: %2</source>
        <translation>Zeile %1: %2</translation>
    </message>
    <message>
        <source>%1 / %2 bytes</source>
        <translation>%1 / %2 Bytes</translation>
    </message>
    <message>
        <source>The script is %1 bytes; the robot stores at most %2. Remove %3 bytes to upload it.</source>
        <translation>Das Skript hat %1 Bytes; der Roboter speichert höchstens %2. Entfernen Sie %3 Bytes, um es hochzuladen.</translation>
    </message>
    <message>
        <source>%1. %2</source>
        <translation>%1. %2</translation>
    </message>
    <message>
        <source>Store the script on the robot (152)</source>
        <translation>Skript auf dem Roboter speichern (152)</translation>
    </message>
    <message>
        <source>Fix the script before uploading it</source>
        <translation>Skript vor dem Hochladen korrigieren</translation>
    </message>
    <message>
        <source>(empty)</source>
        <translation>(leer)</translation>
    </message>
    <message>
        <source>%1 (not readable: %2)</source>
        <translation>%1 (nicht lesbar: %2)</translation>
    </message>
    <message>
        <source>The robot&apos;s script matches what was sent: %1</source>
        <translation>Das Skript des Roboters stimmt mit dem Gesendeten überein: %1</translation>
    </message>
    <message>
        <source>The robot&apos;s script differs from what was sent.
On the robot: %1
Sent: %2</source>
        <translation>Das Skript des Roboters weicht vom Gesendeten ab.
Auf dem Roboter: %1
Gesendet: %2</translation>
    </message>
    <message>
        <source>nothing uploaded yet</source>
        <translation>noch nichts hochgeladen</translation>
    </message>
    <message>
        <source>Asking for the robot&apos;s script…</source>
        <translation>Der Roboter wird nach seinem Skript gefragt…</translation>
    </message>
    <message>
        <source>No script came back: %1</source>
        <translation>Kein Skript kam zurück: %1</translation>
    </message>
    <message>
        <source>Uploaded (152): %1 / %2 bytes. Play (153) runs the script; Show Script (154) reads it back.</source>
        <translation>Hochgeladen (152): %1 / %2 Bytes. Play (153) führt das Skript aus; Show Script (154) liest es zurück.</translation>
    </message>
    <message>
        <source>Play (153) sent. While the script waits (155–158) the Create hears no command, not even a stop; it listens again when the script ends.</source>
        <translation>Play (153) gesendet. Während das Skript wartet (155–158), hört der Create keinen Befehl, nicht einmal einen Halt; er hört wieder zu, wenn das Skript endet.</translation>
    </message>
</context>
<context>
    <name>SelectedRobotView</name>
    <message>
        <source>Recording stopped: %1</source>
        <translation>Aufzeichnung beendet: %1</translation>
    </message>
    <message>
        <source>A recording is replayed: there is no robot to command. Select a connected robot.</source>
        <translation>Eine Aufzeichnung wird abgespielt: Es gibt keinen Roboter, dem man Befehle geben kann. Wählen Sie einen verbundenen Roboter.</translation>
    </message>
    <message>
        <source>Not connected: choose the robot&apos;s connection above and press Connect.</source>
        <translation>Nicht verbunden: Wählen Sie oben die Verbindung des Roboters und drücken Sie Verbinden.</translation>
    </message>
    <message>
        <source>Connecting to the robot: the commands work once it answers.</source>
        <translation>Verbindung zum Roboter wird aufgebaut: Die Befehle wirken, sobald er antwortet.</translation>
    </message>
    <message>
        <source>The link to the robot is lost: the commands work again once it reconnects.</source>
        <translation>Die Verbindung zum Roboter ist verloren: Die Befehle wirken wieder, sobald sie zurück ist.</translation>
    </message>
</context>
<context>
    <name>SensorGauges</name>
    <message>
        <source>STALE — no fresh data from the robot</source>
        <translation>VERALTET — keine neuen Daten vom Roboter</translation>
    </message>
    <message>
        <source>Battery</source>
        <translation>Akku</translation>
    </message>
    <message>
        <source>Drive</source>
        <translation>Antrieb</translation>
    </message>
    <message>
        <source>Motors and dirt</source>
        <translation>Motoren und Schmutz</translation>
    </message>
    <message>
        <source>Cargo bay</source>
        <translation>Laderaum</translation>
    </message>
    <message>
        <source>Charge</source>
        <translation>Ladung</translation>
    </message>
    <message>
        <source>Current</source>
        <translation>Strom</translation>
    </message>
    <message>
        <source>Temperature</source>
        <translation>Temperatur</translation>
    </message>
    <message>
        <source>Charging</source>
        <translation>Laden</translation>
    </message>
    <message>
        <source>Charging sources</source>
        <translation>Ladequellen</translation>
    </message>
    <message>
        <source>Requested velocity</source>
        <translation>Angeforderte Geschwindigkeit</translation>
    </message>
    <message>
        <source>Requested radius</source>
        <translation>Angeforderter Radius</translation>
    </message>
    <message>
        <source>Left wheel motor</source>
        <translation>Linker Radmotor</translation>
    </message>
    <message>
        <source>Right wheel motor</source>
        <translation>Rechter Radmotor</translation>
    </message>
    <message>
        <source>Main brush motor</source>
        <translation>Hauptbürstenmotor</translation>
    </message>
    <message>
        <source>Side brush motor</source>
        <translation>Seitenbürstenmotor</translation>
    </message>
    <message>
        <source>Dirt detect</source>
        <translation>Schmutzerkennung</translation>
    </message>
    <message>
        <source>Analog input</source>
        <translation>Analogeingang</translation>
    </message>
    <message>
        <source>Baud rate change</source>
        <translation>Baudratenwechsel</translation>
    </message>
    <message>
        <source>Digital input %1</source>
        <translation>Digitaleingang %1</translation>
    </message>
    <message>
        <source>%1 of %2 mAh</source>
        <translation>%1 von %2 mAh</translation>
    </message>
    <message>
        <source>discharging</source>
        <translation>entlädt</translation>
    </message>
    <message>
        <source>charging</source>
        <translation>lädt</translation>
    </message>
    <message>
        <source>no current</source>
        <translation>kein Strom</translation>
    </message>
    <message>
        <source>Not charging</source>
        <translation>Lädt nicht</translation>
    </message>
    <message>
        <source>Reconditioning</source>
        <translation>Rekonditionierung</translation>
    </message>
    <message>
        <source>Full charging</source>
        <translation>Vollladung</translation>
    </message>
    <message>
        <source>Trickle charging</source>
        <translation>Erhaltungsladung</translation>
    </message>
    <message>
        <source>Waiting</source>
        <translation>Wartet</translation>
    </message>
    <message>
        <source>Charging fault</source>
        <translation>Ladefehler</translation>
    </message>
    <message>
        <source>Unknown (%1)</source>
        <translation>Unbekannt (%1)</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source> + </source>
        <translation> + </translation>
    </message>
    <message>
        <source>forward</source>
        <translation>vorwärts</translation>
    </message>
    <message>
        <source>backward</source>
        <translation>rückwärts</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>angehalten</translation>
    </message>
    <message>
        <source>straight</source>
        <translation>geradeaus</translation>
    </message>
    <message>
        <source>radius %1</source>
        <translation>Radius %1</translation>
    </message>
    <message>
        <source>turn in place cw</source>
        <translation>auf der Stelle im UZS</translation>
    </message>
    <message>
        <source>radius -1</source>
        <translation>Radius -1</translation>
    </message>
    <message>
        <source>turn in place ccw</source>
        <translation>auf der Stelle gegen UZS</translation>
    </message>
    <message>
        <source>radius 1</source>
        <translation>Radius 1</translation>
    </message>
    <message>
        <source>turning left</source>
        <translation>Linkskurve</translation>
    </message>
    <message>
        <source>turning right</source>
        <translation>Rechtskurve</translation>
    </message>
    <message>
        <source>%1 V on pin 4</source>
        <translation>%1 V an Pin 4</translation>
    </message>
    <message>
        <source>high</source>
        <translation>High</translation>
    </message>
    <message>
        <source>low</source>
        <translation>Low</translation>
    </message>
    <message>
        <source>pin %1</source>
        <translation>Pin %1</translation>
    </message>
    <message>
        <source>asserted (low)</source>
        <translation>aktiv (Low)</translation>
    </message>
    <message>
        <source>idle (high)</source>
        <translation>inaktiv (High)</translation>
    </message>
    <message>
        <source>Voltage</source>
        <translation>Spannung</translation>
    </message>
    <message>
        <source>REPLAY FINISHED — the recording has ended</source>
        <translation>WIEDERGABE BEENDET — die Aufzeichnung ist zu Ende</translation>
    </message>
    <message>
        <source>%1 mΩ</source>
        <translation>%1 mΩ</translation>
    </message>
    <message>
        <source>, </source>
        <translation>, </translation>
    </message>
    <message>
        <source>Measured %1, on an earlier connection.</source>
        <translation>Gemessen %1, bei einer früheren Verbindung.</translation>
    </message>
    <message>
        <source>Capacity measured so far: %1.</source>
        <translation>Bisher gemessene Kapazität: %1.</translation>
    </message>
    <message>
        <source>Pack health</source>
        <translation>Akkuzustand</translation>
    </message>
    <message>
        <source>%1, estimated from voltage</source>
        <translation>%1, aus der Spannung geschätzt</translation>
    </message>
    <message>
        <source>The robot guessed this charge from its voltage as it booted: until a full charge it is an estimate, and a worn pack&apos;s voltage sags under load, so it reads low.</source>
        <translation>Der Roboter hat diese Ladung beim Start aus seiner Spannung geschätzt: Bis zu einer Vollladung ist sie nur eine Schätzung, und die Spannung eines verschlissenen Akkus sackt unter Last ab, sodass sie zu niedrig anzeigt.</translation>
    </message>
</context>
<context>
    <name>SensorHistory</name>
    <message>
        <source>No channels to export.</source>
        <translation>Keine Kanäle zum Exportieren.</translation>
    </message>
    <message>
        <source>The time range to export is not a number.</source>
        <translation>Der zu exportierende Zeitbereich ist keine Zahl.</translation>
    </message>
    <message>
        <source>Packet %1 is not a sensor packet of the %2.</source>
        <translation>Paket %1 ist kein Sensorpaket des %2.</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>Cannot save %1: %2</source>
        <translation>%1 kann nicht gespeichert werden: %2</translation>
    </message>
</context>
<context>
    <name>SensorPlots</name>
    <message>
        <source>%1 min</source>
        <translation>%1 min</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Pause or resume following the newest sample (Space)</source>
        <translation>Mitlaufen mit dem neuesten Messwert anhalten oder fortsetzen (Leertaste)</translation>
    </message>
    <message>
        <source>How much time the plots show</source>
        <translation>Zeitspanne, die die Diagramme zeigen</translation>
    </message>
    <message>
        <source>&amp;Window</source>
        <translation>&amp;Zeitfenster</translation>
    </message>
    <message>
        <source>Add plot</source>
        <translation>Diagramm hinzufügen</translation>
    </message>
    <message>
        <source>Add another plot below the others</source>
        <translation>Weiteres Diagramm unter den anderen hinzufügen</translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation>CSV exportieren</translation>
    </message>
    <message>
        <source>Write the plotted channels to a CSV file</source>
        <translation>Dargestellte Kanäle in eine CSV-Datei schreiben</translation>
    </message>
    <message>
        <source>Visible range…</source>
        <translation>Sichtbarer Bereich…</translation>
    </message>
    <message>
        <source>Whole history…</source>
        <translation>Gesamter Verlauf…</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Fortsetzen</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Live</source>
        <translation>Live</translation>
    </message>
    <message>
        <source>There is no sensor history to export.</source>
        <translation>Es gibt keinen Sensorverlauf zum Exportieren.</translation>
    </message>
    <message>
        <source>No channels are plotted.</source>
        <translation>Es werden keine Kanäle dargestellt.</translation>
    </message>
    <message>
        <source>Export the visible range</source>
        <translation>Sichtbaren Bereich exportieren</translation>
    </message>
    <message>
        <source>Export the whole history</source>
        <translation>Gesamten Verlauf exportieren</translation>
    </message>
    <message>
        <source>CSV files (*.csv);;All files (*)</source>
        <translation>CSV-Dateien (*.csv);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Export fehlgeschlagen</translation>
    </message>
    <message>
        <source>Paused: drag or arrows pan, wheel or +/- zoom, Space resumes</source>
        <translation>Angehalten: Ziehen oder Pfeiltasten verschieben, Mausrad oder +/- zoomt, Leertaste setzt fort</translation>
    </message>
    <message>
        <source>Not live: no fresh data</source>
        <translation>Nicht live: keine frischen Daten</translation>
    </message>
    <message>
        <source>Replay finished</source>
        <translation>Wiedergabe beendet</translation>
    </message>
    <message>
        <source>Replay, not live</source>
        <translation>Wiedergabe, nicht live</translation>
    </message>
</context>
<context>
    <name>SettingsFile</name>
    <message>
        <source>file damaged</source>
        <translation>Datei beschädigt</translation>
    </message>
    <message>
        <source>file unreadable</source>
        <translation>Datei nicht lesbar</translation>
    </message>
    <message>
        <source>settings version %1, not %2</source>
        <translation>Einstellungsversion %1, nicht %2</translation>
    </message>
    <message>
        <source>Settings not loaded (%1) and not kept aside: %2</source>
        <translation>Einstellungen nicht geladen (%1) und nicht beiseitegelegt: %2</translation>
    </message>
    <message>
        <source>Settings reset to defaults: %1; kept as %2</source>
        <translation>Einstellungen auf Standardwerte zurückgesetzt: %1; aufbewahrt als %2</translation>
    </message>
</context>
<context>
    <name>SevenSegmentDisplay</name>
    <message>
        <source>digit %1 dark</source>
        <translation>Ziffer %1 dunkel</translation>
    </message>
    <message>
        <source>digit %1 segments %2</source>
        <translation>Ziffer %1 Segmente %2</translation>
    </message>
    <message>
        <source>Lit: %1.</source>
        <translation>Leuchtet: %1.</translation>
    </message>
    <message>
        <source>Arrow keys choose a segment, Space switches it.</source>
        <translation>Pfeiltasten wählen ein Segment, die Leertaste schaltet es um.</translation>
    </message>
</context>
<context>
    <name>SignalBars</name>
    <message>
        <source>L</source>
        <translation>L</translation>
    </message>
    <message>
        <source>FL</source>
        <translation>VL</translation>
    </message>
    <message>
        <source>FR</source>
        <translation>VR</translation>
    </message>
    <message>
        <source>R</source>
        <translation>R</translation>
    </message>
    <message>
        <source>CL</source>
        <translation>ML</translation>
    </message>
    <message>
        <source>CR</source>
        <translation>MR</translation>
    </message>
    <message>
        <source>Cliff</source>
        <translation>Abgrund</translation>
    </message>
    <message>
        <source>Light bump</source>
        <translation>Lichtstoßfänger</translation>
    </message>
    <message>
        <source>Signal bars</source>
        <translation>Signalbalken</translation>
    </message>
    <message>
        <source>cliff</source>
        <comment>under a bar</comment>
        <translation>Abgrund</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Licht</translation>
    </message>
    <message>
        <source>light</source>
        <comment>under a bar</comment>
        <translation>Licht</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>, </source>
        <translation>, </translation>
    </message>
    <message>
        <source>Stale: %1</source>
        <translation>Veraltet: %1</translation>
    </message>
    <message>
        <source>Cliff and light-bump signals</source>
        <translation>Abgrund- und Lichtstoßfängersignale</translation>
    </message>
    <message>
        <source>Cliff signals</source>
        <translation>Abgrundsignale</translation>
    </message>
    <message>
        <source>STALE — %1</source>
        <translation>VERALTET — %1</translation>
    </message>
</context>
<context>
    <name>SongComposer</name>
    <message>
        <source>Song slot:</source>
        <translation>Liedplatz:</translation>
    </message>
    <message>
        <source>Song slots</source>
        <translation>Liedplätze</translation>
    </message>
    <message>
        <source>Add note</source>
        <translation>Note hinzufügen</translation>
    </message>
    <message>
        <source>Add a note after the selected one</source>
        <translation>Eine Note nach der ausgewählten einfügen</translation>
    </message>
    <message>
        <source>Remove note</source>
        <translation>Note entfernen</translation>
    </message>
    <message>
        <source>Remove the selected note</source>
        <translation>Ausgewählte Note entfernen</translation>
    </message>
    <message>
        <source> st</source>
        <translation> HT</translation>
    </message>
    <message>
        <source>Semitones to transpose by; negative is down</source>
        <translation>Halbtöne zum Transponieren; negativ ist abwärts</translation>
    </message>
    <message>
        <source>Semitones</source>
        <translation>Halbtöne</translation>
    </message>
    <message>
        <source>Transpose</source>
        <translation>Transponieren</translation>
    </message>
    <message>
        <source>Move every note by the semitones shown</source>
        <translation>Alle Noten um die angezeigten Halbtöne verschieben</translation>
    </message>
    <message>
        <source>Multiply every duration: 2 plays twice as slow, 0.5 twice as fast</source>
        <translation>Alle Dauern multiplizieren: 2 spielt halb so schnell, 0,5 doppelt so schnell</translation>
    </message>
    <message>
        <source>Duration factor</source>
        <translation>Dauerfaktor</translation>
    </message>
    <message>
        <source>Scale durations</source>
        <translation>Dauern skalieren</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>Note</translation>
    </message>
    <message>
        <source>1/64 s</source>
        <translation>1/64 s</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <source>Note: a name such as C#5, a MIDI number 31..127 or &quot;rest&quot;. Duration in 1/64 s (0..255) or in milliseconds.</source>
        <translation>Note: ein Name wie C#5, eine MIDI-Nummer 31..127 oder „Pause“. Dauer in 1/64 s (0..255) oder in Millisekunden.</translation>
    </message>
    <message>
        <source>Notes</source>
        <translation>Noten</translation>
    </message>
    <message>
        <source>One row a note: the note, its duration in 1/64 s and in ms. Arrow keys move, F2 or typing edits a cell.</source>
        <translation>Eine Zeile pro Note: die Note, ihre Dauer in 1/64 s und in ms. Pfeiltasten bewegen, F2 oder Tippen bearbeitet eine Zelle.</translation>
    </message>
    <message>
        <source>Upload slot</source>
        <translation>Platz hochladen</translation>
    </message>
    <message>
        <source>Send this slot&apos;s song to the robot (140)</source>
        <translation>Das Lied dieses Platzes an den Roboter senden (140)</translation>
    </message>
    <message>
        <source>Upload all</source>
        <translation>Alle hochladen</translation>
    </message>
    <message>
        <source>Send every slot that has notes (140)</source>
        <translation>Alle Plätze mit Noten senden (140)</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Abspielen</translation>
    </message>
    <message>
        <source>Upload this slot&apos;s song and play it on the robot (140, 141)</source>
        <translation>Das Lied dieses Platzes hochladen und auf dem Roboter abspielen (140, 141)</translation>
    </message>
    <message>
        <source>Stop preview</source>
        <translation>Vorschau stoppen</translation>
    </message>
    <message>
        <source>Preview</source>
        <translation>Vorschau</translation>
    </message>
    <message>
        <source>Play this slot on the computer</source>
        <translation>Diesen Platz auf dem Computer abspielen</translation>
    </message>
    <message>
        <source>Square tone</source>
        <translation>Rechteckton</translation>
    </message>
    <message>
        <source>Sine tone</source>
        <translation>Sinuston</translation>
    </message>
    <message>
        <source>How Preview and Export WAV sound; the robot&apos;s speaker sounds closer to square</source>
        <translation>Klang von Vorschau und WAV-Export; der Lautsprecher des Roboters klingt eher nach Rechteck</translation>
    </message>
    <message>
        <source>Tone for Preview and Export WAV</source>
        <translation>Klang für Vorschau und WAV-Export</translation>
    </message>
    <message>
        <source>Load…</source>
        <translation>Laden…</translation>
    </message>
    <message>
        <source>Replace the songs with a song file</source>
        <translation>Lieder durch eine Lieddatei ersetzen</translation>
    </message>
    <message>
        <source>Save…</source>
        <translation>Speichern…</translation>
    </message>
    <message>
        <source>Save the songs as JSON</source>
        <translation>Lieder als JSON speichern</translation>
    </message>
    <message>
        <source>Examples</source>
        <translation>Beispiele</translation>
    </message>
    <message>
        <source>Put an example song in this slot</source>
        <translation>Ein Beispiellied in diesen Platz legen</translation>
    </message>
    <message>
        <source>Import RTTTL…</source>
        <translation>RTTTL importieren…</translation>
    </message>
    <message>
        <source>Notes from a ring-tone text</source>
        <translation>Noten aus einem Klingelton-Text</translation>
    </message>
    <message>
        <source>Import MIDI…</source>
        <translation>MIDI importieren…</translation>
    </message>
    <message>
        <source>The melody of a MIDI file</source>
        <translation>Die Melodie einer MIDI-Datei</translation>
    </message>
    <message>
        <source>Export WAV…</source>
        <translation>WAV exportieren…</translation>
    </message>
    <message>
        <source>This slot as a WAV sound file</source>
        <translation>Dieser Platz als WAV-Audiodatei</translation>
    </message>
    <message>
        <source>Preview plays on %1.</source>
        <translation>Die Vorschau spielt über %1.</translation>
    </message>
    <message>
        <source>No audio output device on this computer, so Preview is off. Export WAV still works.</source>
        <translation>Dieser Computer hat kein Audioausgabegerät, daher ist die Vorschau aus. WAV-Export funktioniert trotzdem.</translation>
    </message>
    <message>
        <source>Load songs</source>
        <translation>Lieder laden</translation>
    </message>
    <message>
        <source>Song files (*.json)</source>
        <translation>Lieddateien (*.json)</translation>
    </message>
    <message>
        <source>Save songs</source>
        <translation>Lieder speichern</translation>
    </message>
    <message>
        <source>Import RTTTL</source>
        <translation>RTTTL importieren</translation>
    </message>
    <message>
        <source>Ring tone, e.g. Beep:d=4,o=5,b=120:c,e,g,c6</source>
        <translation>Klingelton, z. B. Beep:d=4,o=5,b=120:c,e,g,c6</translation>
    </message>
    <message>
        <source>Import MIDI</source>
        <translation>MIDI importieren</translation>
    </message>
    <message>
        <source>MIDI files (*.mid *.midi)</source>
        <translation>MIDI-Dateien (*.mid *.midi)</translation>
    </message>
    <message>
        <source>Export WAV</source>
        <translation>WAV exportieren</translation>
    </message>
    <message>
        <source>WAV files (*.wav)</source>
        <translation>WAV-Dateien (*.wav)</translation>
    </message>
    <message>
        <source>The %1 has %2 song slots; %3 song(s) in higher slots are kept but hidden.</source>
        <translation>Der %1 hat %2 Liedplätze; %3 Lied(er) in höheren Plätzen bleiben erhalten, werden aber ausgeblendet.</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Song %1: 1 note</source>
        <translation>Lied %1: 1 Note</translation>
    </message>
    <message numerus="yes">
        <source>Song %1: %n notes</source>
        <translation>
            <numerusform>Lied %1: %n Note</numerusform>
            <numerusform>Lied %1: %n Noten</numerusform>
        </translation>
    </message>
    <message>
        <source>Song slot %1 is outside 0..%2 on this robot</source>
        <translation>Liedplatz %1 liegt bei diesem Roboter außerhalb von 0..%2</translation>
    </message>
    <message>
        <source>A song holds at most %1 notes, not %2</source>
        <translation>Ein Lied fasst höchstens %1 Noten, nicht %2</translation>
    </message>
    <message>
        <source>Slot %1: %2, %3 s (%4/64 s)</source>
        <translation>Platz %1: %2, %3 s (%4/64 s)</translation>
    </message>
    <message>
        <source>1 note</source>
        <translation>1 Note</translation>
    </message>
    <message numerus="yes">
        <source>%n notes</source>
        <translation>
            <numerusform>%n Note</numerusform>
            <numerusform>%n Noten</numerusform>
        </translation>
    </message>
    <message>
        <source>Note %1: &quot;%2&quot; is not a note. Use a name from G1 to G9 (e.g. C#5), a MIDI number 31..127, or &quot;rest&quot;.</source>
        <translation>Note %1: „%2“ ist keine Note. Verwenden Sie einen Namen von G1 bis G9 (z. B. C#5), eine MIDI-Nummer 31..127 oder „Pause“.</translation>
    </message>
    <message>
        <source>Note %1: &quot;%2&quot; is not a whole number of 1/64 s</source>
        <translation>Note %1: „%2“ ist keine ganze Zahl von 1/64 s</translation>
    </message>
    <message>
        <source>Note %1: &quot;%2&quot; is not a number of milliseconds</source>
        <translation>Note %1: „%2“ ist keine Zahl von Millisekunden</translation>
    </message>
    <message>
        <source>Note %1: %2 is outside 0..255/64 s (0..3984 ms)</source>
        <translation>Note %1: %2 liegt außerhalb von 0..255/64 s (0..3984 ms)</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>A song holds at most %1 notes</source>
        <translation>Ein Lied fasst höchstens %1 Noten</translation>
    </message>
    <message>
        <source>Transposed slot %1 by %2 semitone(s).</source>
        <translation>Platz %1 um %2 Halbtöne transponiert.</translation>
    </message>
    <message>
        <source>Durations in slot %1 multiplied by %2.</source>
        <translation>Dauern in Platz %1 mit %2 multipliziert.</translation>
    </message>
    <message>
        <source>%1 refused: %2</source>
        <translation>%1 abgelehnt: %2</translation>
    </message>
    <message>
        <source>%1 Warning: %2</source>
        <translation>%1 Warnung: %2</translation>
    </message>
    <message>
        <source>%1 sent.</source>
        <translation>%1 gesendet.</translation>
    </message>
    <message>
        <source>Song %1</source>
        <translation>Lied %1</translation>
    </message>
    <message>
        <source>Song %1 refused: %2</source>
        <translation>Lied %1 abgelehnt: %2</translation>
    </message>
    <message>
        <source>Nothing to upload: every slot is empty.</source>
        <translation>Nichts hochzuladen: Alle Plätze sind leer.</translation>
    </message>
    <message>
        <source>Uploaded songs %1.</source>
        <translation>Lieder %1 hochgeladen.</translation>
    </message>
    <message>
        <source> Warning: </source>
        <translation> Warnung: </translation>
    </message>
    <message>
        <source>Play song %1</source>
        <translation>Lied %1 abspielen</translation>
    </message>
    <message>
        <source>Playing: unknown (packet 37 not streamed)</source>
        <translation>Wiedergabe: unbekannt (Paket 37 nicht im Datenstrom)</translation>
    </message>
    <message>
        <source>No song playing</source>
        <translation>Kein Lied wird gespielt</translation>
    </message>
    <message>
        <source>Playing song %1: %2 of %3 s</source>
        <translation>Lied %1 wird gespielt: %2 von %3 s</translation>
    </message>
    <message>
        <source>Playing song %1</source>
        <translation>Lied %1 wird gespielt</translation>
    </message>
    <message>
        <source>Saved %1.</source>
        <translation>%1 gespeichert.</translation>
    </message>
    <message>
        <source> The open songs are unchanged.</source>
        <translation> Die geöffneten Lieder sind unverändert.</translation>
    </message>
    <message>
        <source>Loaded %1.</source>
        <translation>%1 geladen.</translation>
    </message>
    <message>
        <source>%1 needs %2 slot(s) but only %3 are left from slot %4 on; nothing was changed.</source>
        <translation>%1 braucht %2 Platz/Plätze, ab Platz %4 sind aber nur %3 frei; nichts wurde geändert.</translation>
    </message>
    <message>
        <source>%1 is in slot %2.</source>
        <translation>%1 liegt in Platz %2.</translation>
    </message>
    <message>
        <source>The ring tone</source>
        <translation>Der Klingelton</translation>
    </message>
    <message>
        <source>%1: %2 notes in slot(s) %3..%4.</source>
        <translation>%1: %2 Noten in Platz/Plätzen %3..%4.</translation>
    </message>
    <message>
        <source>Imported %1 melody notes into slot(s) %2..%3.</source>
        <translation>%1 Melodienoten in Platz/Plätze %2..%3 importiert.</translation>
    </message>
    <message>
        <source> %1 notes did not fit in the remaining slots and were left out.</source>
        <translation> %1 Noten passten nicht in die restlichen Plätze und wurden weggelassen.</translation>
    </message>
    <message>
        <source> %1 notes longer than 255/64 s were shortened to 255.</source>
        <translation> %1 Noten, die länger als 255/64 s waren, wurden auf 255 gekürzt.</translation>
    </message>
    <message>
        <source>Slot %1 is empty; there is nothing to export.</source>
        <translation>Platz %1 ist leer; es gibt nichts zu exportieren.</translation>
    </message>
    <message>
        <source>Exported slot %1 to %2.</source>
        <translation>Platz %1 nach %2 exportiert.</translation>
    </message>
    <message>
        <source>No audio output device on this computer, so Preview is off.</source>
        <translation>Dieser Computer hat kein Audioausgabegerät, daher ist die Vorschau aus.</translation>
    </message>
    <message>
        <source>Slot %1 is empty; there is nothing to preview.</source>
        <translation>Platz %1 ist leer; es gibt nichts vorzuspielen.</translation>
    </message>
    <message>
        <source>%1 cannot play 16-bit mono sound at %2 Hz; use Export WAV instead.</source>
        <translation>%1 kann keinen 16-Bit-Mono-Ton mit %2 Hz abspielen; verwenden Sie stattdessen den WAV-Export.</translation>
    </message>
    <message>
        <source>Play song %1 refused: %2</source>
        <translation>Lied %1 abspielen abgelehnt: %2</translation>
    </message>
    <message>
        <source>song slot 4 may not play on some firmware (ERRATA 13)</source>
        <translation>Liedplatz 4 spielt auf mancher Firmware nicht (ERRATA 13)</translation>
    </message>
    <message>
        <source>Nothing to play: slot %1 has no notes.</source>
        <translation>Nichts abzuspielen: Platz %1 hat keine Noten.</translation>
    </message>
    <message>
        <source>Song %1 as shown: uploaded (140) and played (141).</source>
        <translation>Lied %1 wie angezeigt: hochgeladen (140) und abgespielt (141).</translation>
    </message>
</context>
<context>
    <name>SongFiles</name>
    <message>
        <source>Not a JSON file: %1 at offset %2</source>
        <translation>Keine JSON-Datei: %1 an Position %2</translation>
    </message>
    <message>
        <source>Not a song file: the top level is not an object</source>
        <translation>Keine Lieddatei: Die oberste Ebene ist kein Objekt</translation>
    </message>
    <message>
        <source>Not a song file: &quot;format&quot; is not &quot;%1&quot;</source>
        <translation>Keine Lieddatei: „format“ ist nicht „%1“</translation>
    </message>
    <message>
        <source>Song file version %1 is not supported; only version %2 is</source>
        <translation>Lieddatei-Version %1 wird nicht unterstützt, nur Version %2</translation>
    </message>
    <message>
        <source>Song file has no &quot;songs&quot; list</source>
        <translation>Lieddatei hat keine „songs“-Liste</translation>
    </message>
    <message>
        <source>Song %1: slot %2 is outside 0..%3 for this robot</source>
        <translation>Lied %1: Platz %2 liegt für diesen Roboter außerhalb von 0..%3</translation>
    </message>
    <message>
        <source>Song %1: slot %2 appears twice</source>
        <translation>Lied %1: Platz %2 kommt doppelt vor</translation>
    </message>
    <message>
        <source>Song in slot %1 has no &quot;notes&quot; list</source>
        <translation>Lied in Platz %1 hat keine „notes“-Liste</translation>
    </message>
    <message>
        <source>Song in slot %1 has %2 notes; a song has 1..%3</source>
        <translation>Lied in Platz %1 hat %2 Noten; ein Lied hat 1..%3</translation>
    </message>
    <message>
        <source>Slot %1, note %2: expected [note 0..127, duration 0..255], got %3</source>
        <translation>Platz %1, Note %2: erwartet [Note 0..127, Dauer 0..255], erhalten: %3</translation>
    </message>
    <message>
        <source>Could not save %1: %2</source>
        <translation>%1 konnte nicht gespeichert werden: %2</translation>
    </message>
    <message>
        <source>Could not open %1: %2</source>
        <translation>%1 konnte nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <source>Cannot transpose by %1: note %2 (%3) would become %4, outside %5..%6</source>
        <translation>Transponieren um %1 nicht möglich: Note %2 (%3) würde zu %4, außerhalb von %5..%6</translation>
    </message>
    <message>
        <source>Cannot scale durations by %1: note %2 would last %3/64 s; durations must stay within 1..255</source>
        <translation>Dauern können nicht mit %1 skaliert werden: Note %2 würde %3/64 s dauern; Dauern müssen im Bereich 1..255 bleiben</translation>
    </message>
    <message>
        <source>rest</source>
        <translation>Pause</translation>
    </message>
</context>
<context>
    <name>SongWave</name>
    <message>
        <source>Could not save %1: %2</source>
        <translation>%1 konnte nicht gespeichert werden: %2</translation>
    </message>
</context>
<context>
    <name>StopAllButton</name>
    <message>
        <source>STOP ALL  (Shift+Esc)</source>
        <translation>ALLE STOPP  (Umschalt+Esc)</translation>
    </message>
    <message>
        <source>Stop every robot at once, whichever is selected: the window&apos;s robots and every robot on the broker.
Shift+Esc does the same from any window; Space or Esc stops the selected robot.</source>
        <translation>Hält jeden Roboter sofort an, egal welcher ausgewählt ist: die Roboter des Fensters und jeden Roboter am Broker.
Umschalt+Esc tut dasselbe aus jedem Fenster; Leertaste oder Esc hält den ausgewählten Roboter an.</translation>
    </message>
    <message>
        <source>Stop all robots</source>
        <translation>Alle Roboter anhalten</translation>
    </message>
</context>
<context>
    <name>TeleopController</name>
    <message>
        <source>Not driving: no live data from the robot, so nobody could see it move. Wait until it streams.</source>
        <translation>Fährt nicht: keine Live-Daten vom Roboter, niemand könnte ihn fahren sehen. Warten Sie, bis er Daten sendet.</translation>
    </message>
    <message>
        <source>Not driving: %1</source>
        <translation>Fährt nicht: %1</translation>
    </message>
    <message>
        <source>Not driving: the robot is in Passive mode and ignores motion. Press Enter Safe to drive.</source>
        <translation>Fährt nicht: Der Roboter ist im Passive-Modus und ignoriert Fahrbefehle. Drücken Sie „Safe aktivieren“, um zu fahren.</translation>
    </message>
    <message>
        <source>Not driving: %1. Put it down on the floor to drive.</source>
        <translation>Fährt nicht: %1. Stellen Sie ihn zum Fahren auf den Boden.</translation>
    </message>
</context>
<context>
    <name>ValueGauge</name>
    <message>
        <source>OUT OF RANGE</source>
        <translation>AUSSER BEREICH</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <source>%1, out of range</source>
        <translation>%1, außerhalb des Bereichs</translation>
    </message>
    <message>
        <source>%1, stale</source>
        <translation>%1, veraltet</translation>
    </message>
    <message>
        <source>%1, unreliable: %2</source>
        <translation>%1, unzuverlässig: %2</translation>
    </message>
</context>
<context>
    <name>mcap::Writer</name>
    <message>
        <source>cannot compress a chunk with %1</source>
        <translation>ein Block lässt sich nicht mit %1 komprimieren</translation>
    </message>
</context>
<context>
    <name>oilink</name>
    <message>
        <source>%1 must be a whole number from %2 to %3, not %4.</source>
        <translation>%1 muss eine ganze Zahl von %2 bis %3 sein, nicht %4.</translation>
    </message>
    <message>
        <source>%1 must be a number of at least 0.</source>
        <translation>%1 muss eine Zahl von mindestens 0 sein.</translation>
    </message>
</context>
<context>
    <name>oilink::ConnectionDoctor</name>
    <message>
        <source>%1 baud</source>
        <translation>%1 Baud</translation>
    </message>
    <message>
        <source>At %1 it answers.</source>
        <translation>Bei %1 antwortet er.</translation>
    </message>
    <message>
        <source>At %1 it answers after Start (it was in Off mode).</source>
        <translation>Bei %1 antwortet er nach Start (er war im Modus Aus).</translation>
    </message>
    <message numerus="yes">
        <source>At %1: %n byte(s) that make no sense.</source>
        <translation>
            <numerusform>Bei %1: %n Byte, das keinen Sinn ergibt.</numerusform>
            <numerusform>Bei %1: %n Bytes, die keinen Sinn ergeben.</numerusform>
        </translation>
    </message>
    <message>
        <source>At %1: nothing comes back, with or without Start.</source>
        <translation>Bei %1: keine Antwort, weder mit noch ohne Start.</translation>
    </message>
    <message>
        <source>Bytes come back, but at no baud do they make sense: a noisy cable, or a device that is not an Open Interface robot.</source>
        <translation>Es kommen Bytes zurück, aber bei keiner Baudrate ergeben sie Sinn: ein gestörtes Kabel oder ein Gerät, das kein Open-Interface-Roboter ist.</translation>
    </message>
    <message>
        <source>Nothing comes back: is the robot on and the cable plugged in? (A sleeping robot cannot be woken over this connection.)</source>
        <translation>Keine Antwort: Ist der Roboter eingeschaltet und das Kabel eingesteckt? (Ein schlafender Roboter lässt sich über diese Verbindung nicht wecken.)</translation>
    </message>
    <message>
        <source>At %1 it answers after the pulse.</source>
        <translation>Bei %1 antwortet er nach dem Impuls.</translation>
    </message>
    <message>
        <source>2 s after the wake pulse, pulsed the BRC pin three times for 19200 baud.</source>
        <translation>2 s nach dem Weckimpuls den BRC-Pin dreimal gepulst für 19200 Baud.</translation>
    </message>
    <message>
        <source>At 19200 baud it answers after the three pulses.</source>
        <translation>Bei 19200 Baud antwortet er nach den drei Impulsen.</translation>
    </message>
    <message>
        <source>It answers Sensors 101: a Roomba 500 or a Create 2 (they answer alike).</source>
        <translation>Er beantwortet Sensors 101: ein Roomba 500 oder ein Create 2 (beide antworten gleich).</translation>
    </message>
    <message>
        <source>It has no packet group 101: a Create.</source>
        <translation>Er hat keine Paketgruppe 101: ein Create.</translation>
    </message>
    <message>
        <source>The robot was asleep; a BRC pulse woke it.</source>
        <translation>Der Roboter schlief; ein BRC-Impuls hat ihn geweckt.</translation>
    </message>
    <message>
        <source>The robot was asleep; a BRC pulse woke it, and it talks at %1 baud.</source>
        <translation>Der Roboter schlief; ein BRC-Impuls hat ihn geweckt, und er spricht mit %1 Baud.</translation>
    </message>
    <message>
        <source>After three BRC pulses the robot now talks at 19200 baud: set the baud to 19200.</source>
        <translation>Nach drei BRC-Impulsen spricht der Roboter jetzt mit 19200 Baud: Baudrate auf 19200 stellen.</translation>
    </message>
    <message>
        <source>Wrong baud: the robot answers at %1 baud, not %2.</source>
        <translation>Falsche Baudrate: Der Roboter antwortet mit %1 Baud, nicht mit %2.</translation>
    </message>
    <message>
        <source>The robot answers as a %1, not as the %2 the connection names.</source>
        <translation>Der Roboter antwortet als %1, nicht als der %2, den die Verbindung nennt.</translation>
    </message>
    <message>
        <source>Roomba 500 or Create 2</source>
        <translation>Roomba 500 oder Create 2</translation>
    </message>
    <message>
        <source>The robot answers at %1 as a %2.</source>
        <translation>Der Roboter antwortet bei %1 als %2.</translation>
    </message>
    <message>
        <source>Bytes come back, but they make no sense. This connection cannot change the bridge&apos;s rate: the robot may talk at another baud than the bridge&apos;s serial port (set the bridge to the robot&apos;s rate, or use its RFC 2217 telnet mode so that each rate can be tried), or the device is not an Open Interface robot.</source>
        <translation>Es kommen Bytes zurück, aber sie ergeben keinen Sinn. Diese Verbindung kann die Rate der Brücke nicht ändern: Der Roboter spricht vielleicht mit einer anderen Baudrate als die serielle Schnittstelle der Brücke (stellen Sie die Brücke auf die Rate des Roboters oder nutzen Sie ihren RFC-2217-Telnet-Modus, damit jede Rate versucht werden kann), oder das Gerät ist kein Open-Interface-Roboter.</translation>
    </message>
    <message>
        <source>The robot answers at %1 as a Roomba 500 or a Create 2. The two answer alike but read their wheel encoders the other way round: name which it is.</source>
        <translation>Der Roboter antwortet mit %1 als Roomba 500 oder Create 2. Beide antworten gleich, lesen ihre Radencoder aber umgekehrt: Geben Sie an, welcher es ist.</translation>
    </message>
    <message>
        <source>Pulsed the BRC pin on the wake line (%1) to wake the robot.</source>
        <translation>Den BRC-Pin über die Weckleitung (%1) gepulst, um den Roboter zu wecken.</translation>
    </message>
    <message>
        <source>Silent so far; a slow robot takes up to 2 s to wake: asking again once it has had that time.</source>
        <translation>Bisher still; ein langsamer Roboter braucht bis zu 2 s zum Aufwachen: erneute Frage, sobald er diese Zeit hatte.</translation>
    </message>
    <message>
        <source>Still silent: pulsed the other line (%1) instead.</source>
        <translation>Immer noch still: stattdessen die andere Leitung (%1) gepulst.</translation>
    </message>
    <message>
        <source>No line wakes it: still silent after BRC pulses on RTS and on DTR. The cable may not carry the BRC pin (press Clean to wake the robot), or the robot is off or unplugged, or asleep on its dock with firmware before release-3.8.2 / release-stm32-3.7.7, which does not wake by BRC there (lift it off the dock, or press Clean).</source>
        <translation>Keine Leitung weckt ihn: immer noch still nach BRC-Impulsen auf RTS und auf DTR. Vielleicht führt das Kabel den BRC-Pin nicht (drücken Sie Clean, um den Roboter zu wecken), oder der Roboter ist aus oder nicht angeschlossen, oder er schläft auf seiner Ladestation mit einer Firmware vor release-3.8.2 / release-stm32-3.7.7, die dort nicht durch BRC aufwacht (heben Sie ihn von der Station oder drücken Sie Clean).</translation>
    </message>
    <message>
        <source>The wake pulse works on %1, not %2: the cable carries the robot&apos;s BRC pin on %1. Set the wake line to %1 (--brc-line %3).</source>
        <translation>Der Weckimpuls wirkt über %1, nicht über %2: Das Kabel führt den BRC-Pin des Roboters auf %1. Stellen Sie die Weckleitung auf %1 (--brc-line %3).</translation>
    </message>
    <message>
        <source>At %1 the robot prints text: &quot;%2&quot;.</source>
        <translation>Bei %1 schreibt der Roboter Text: &quot;%2&quot;.</translation>
    </message>
    <message>
        <source>At %1 it prints text but does not answer.</source>
        <translation>Bei %1 schreibt er Text, antwortet aber nicht.</translation>
    </message>
    <message>
        <source>At %1 the robot prints its charging status (&quot;%2&quot;): the baud and the cable are right, and it is a Roomba on its dock. It does not answer there: asleep on its dock (firmware before release-3.8.2 / release-stm32-3.7.7 does not wake by BRC there). Press Clean, or lift it off the dock.</source>
        <translation>Bei %1 schreibt der Roboter seinen Ladezustand (&quot;%2&quot;): Baudrate und Kabel stimmen, und es ist ein Roomba auf seiner Ladestation. Dort antwortet er nicht: er schläft auf der Ladestation (Firmware vor release-3.8.2 / release-stm32-3.7.7 wacht dort durch BRC nicht auf). Clean drücken oder ihn von der Ladestation heben.</translation>
    </message>
    <message>
        <source>It prints its charging status (&quot;%1&quot;): it is on its dock.</source>
        <translation>Er schreibt seinen Ladezustand (&quot;%1&quot;): er steht auf seiner Ladestation.</translation>
    </message>
    <message>
        <source>It answers Sensors 0 but has no packet 35 (OI mode): a Roomba 400 series, which speaks the older SCI (2005).</source>
        <translation>Er antwortet auf Sensors 0, hat aber kein Paket 35 (OI-Modus): ein Roomba der 400er-Serie, der das ältere SCI (2005) spricht.</translation>
    </message>
    <message>
        <source>It printed &quot;%1&quot;: the text a Roomba 400 prints as it starts up, not a charging status.</source>
        <translation>Er schrieb &quot;%1&quot;: den Text, den ein Roomba 400 beim Starten schreibt, keinen Ladezustand.</translation>
    </message>
</context>
<context>
    <name>oilink::ReplayTransport</name>
    <message>
        <source>replay of %1</source>
        <translation>Wiedergabe von %1</translation>
    </message>
</context>
<context>
    <name>oilink::RobotLink</name>
    <message>
        <source>bunched link (frames every %1 s)</source>
        <translation>gebündelte Verbindung (Frames alle %1 s)</translation>
    </message>
</context>
<context>
    <name>oilink::RobotLinkThread</name>
    <message>
        <source>not connected: the command was not sent</source>
        <translation>nicht verbunden: der Befehl wurde nicht gesendet</translation>
    </message>
    <message>
        <source>not connected: the sensor query was not sent</source>
        <translation>nicht verbunden: die Sensorabfrage wurde nicht gesendet</translation>
    </message>
    <message>
        <source>not connected: Show Script was not sent</source>
        <translation>nicht verbunden: Show Script wurde nicht gesendet</translation>
    </message>
    <message>
        <source>not connected: there is nothing to check</source>
        <translation>nicht verbunden: es gibt nichts zu prüfen</translation>
    </message>
    <message>
        <source>not connected: there is nothing to wake</source>
        <translation>nicht verbunden: es gibt nichts zu wecken</translation>
    </message>
</context>
<context>
    <name>oilink::SerialTransport</name>
    <message>
        <source>%1: no such port</source>
        <translation>%1: Anschluss nicht vorhanden</translation>
    </message>
    <message>
        <source>%1: permission denied (is your user in the dialout group?)</source>
        <translation>%1: Zugriff verweigert (ist Ihr Benutzer in der Gruppe dialout?)</translation>
    </message>
    <message>
        <source>%1: port busy (another program has it open)</source>
        <translation>%1: Anschluss belegt (ein anderes Programm hat ihn geöffnet)</translation>
    </message>
    <message>
        <source>%1: cannot open: %2</source>
        <translation>%1: kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <source>the port went away</source>
        <translation>der Anschluss ist verschwunden</translation>
    </message>
    <message>
        <source>%1: the port has no RTS or DTR line to pulse the BRC pin with</source>
        <translation>%1: Der Anschluss hat keine RTS- oder DTR-Leitung, um den BRC-Pin zu pulsen</translation>
    </message>
</context>
<context>
    <name>oilink::TcpTransport</name>
    <message>
        <source>connection refused</source>
        <translation>Verbindung abgelehnt</translation>
    </message>
    <message>
        <source>no such host</source>
        <translation>Rechner nicht gefunden</translation>
    </message>
    <message>
        <source>no answer (timed out)</source>
        <translation>keine Antwort (Zeitüberschreitung)</translation>
    </message>
    <message>
        <source>network unreachable</source>
        <translation>Netzwerk nicht erreichbar</translation>
    </message>
    <message>
        <source>%1: the bridge closed the connection</source>
        <translation>%1: die Brücke hat die Verbindung geschlossen</translation>
    </message>
    <message>
        <source>%1: connection lost (%2)</source>
        <translation>%1: Verbindung verloren (%2)</translation>
    </message>
    <message>
        <source>%1: no answer (timed out)</source>
        <translation>%1: keine Antwort (Zeitüberschreitung)</translation>
    </message>
    <message>
        <source>%1: the bridge closed the connection: %2</source>
        <translation>%1: die Brücke hat die Verbindung geschlossen: %2</translation>
    </message>
    <message>
        <source>%1: raw TCP carries no modem lines, so it cannot wake the robot or keep it awake</source>
        <translation>%1: Rohes TCP überträgt keine Modemleitungen, kann den Roboter also weder wecken noch wach halten</translation>
    </message>
</context>
<context>
    <name>oilink::Transport</name>
    <message>
        <source>%1 cannot reach the robot&apos;s BRC pin</source>
        <translation>%1 erreicht den BRC-Pin des Roboters nicht</translation>
    </message>
    <message>
        <source>%1: the wake line is set to none, so the cable is taken to have no BRC wire</source>
        <translation>%1: Die Weckleitung ist auf keine gestellt, das Kabel gilt also als ohne BRC-Ader</translation>
    </message>
</context>
</TS>

<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE" sourcelanguage="en_GB">
<context>
    <name>RouterCommands</name>
    <message>
        <source>Add %1</source>
        <translation>%1 hinzufügen</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>Trennen</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Verschieben</translation>
    </message>
    <message>
        <source>Connect %1 to %2</source>
        <translation>%1 mit %2 verbinden</translation>
    </message>
    <message>
        <source>Set %1.%2</source>
        <translation>%1.%2 setzen</translation>
    </message>
    <message>
        <source>Rename %1 to %2</source>
        <translation>%1 in %2 umbenennen</translation>
    </message>
</context>
<context>
    <name>StudioOptions</name>
    <message>
        <source>semhap studio: watch and tune semantic haptic feedback on a simulated task.</source>
        <translation>semhap studio: semantische haptische Rückmeldung an einer simulierten Aufgabe beobachten und abstimmen.</translation>
    </message>
    <message>
        <source>Scene: a bundled name or an MJCF file.</source>
        <translation>Szene: ein mitgelieferter Name oder eine MJCF-Datei.</translation>
    </message>
    <message>
        <source>scene</source>
        <translation>szene</translation>
    </message>
    <message>
        <source>Router: a preset name or a semhap.router/1 file.</source>
        <translation>Router: ein Vorlagenname oder eine semhap.router/1-Datei.</translation>
    </message>
    <message>
        <source>router</source>
        <translation>router</translation>
    </message>
    <message>
        <source>name</source>
        <translation>name</translation>
    </message>
    <message>
        <source>The operator&apos;s seed.</source>
        <translation>Startwert des Bedieners.</translation>
    </message>
    <message>
        <source>n</source>
        <translation>n</translation>
    </message>
    <message>
        <source>Cubes in play (default: the scene&apos;s).</source>
        <translation>Anzahl der Würfel (Standard: wie in der Szene).</translation>
    </message>
    <message>
        <source>Simulated seconds per real second.</source>
        <translation>Simulierte Sekunden pro echter Sekunde.</translation>
    </message>
    <message>
        <source>factor</source>
        <translation>faktor</translation>
    </message>
    <message>
        <source>Open paused.</source>
        <translation>Angehalten starten.</translation>
    </message>
    <message>
        <source>Grab the whole window to this PNG, then quit.</source>
        <translation>Das ganze Fenster in diese PNG-Datei aufnehmen, dann beenden.</translation>
    </message>
    <message>
        <source>file.png</source>
        <translation>datei.png</translation>
    </message>
    <message>
        <source>Grab (with --screenshot) and quit after this many seconds.</source>
        <translation>Nach so vielen Sekunden aufnehmen (mit --screenshot) und beenden.</translation>
    </message>
    <message>
        <source>seconds</source>
        <translation>sekunden</translation>
    </message>
    <message>
        <source>Window size, e.g. 1280x800.</source>
        <translation>Fenstergröße, z. B. 1280x800.</translation>
    </message>
    <message>
        <source>WxH</source>
        <translation>BxH</translation>
    </message>
    <message>
        <source>User interface language: en or de.</source>
        <translation>Sprache der Oberfläche: en oder de.</translation>
    </message>
    <message>
        <source>code</source>
        <translation>code</translation>
    </message>
    <message>
        <source>UDP port of the network pose input (0: off).</source>
        <translation>UDP-Port der Posen-Eingabe über das Netzwerk (0: aus).</translation>
    </message>
    <message>
        <source>port</source>
        <translation>port</translation>
    </message>
    <message>
        <source>Ignore the saved window layout.</source>
        <translation>Das gespeicherte Fensterlayout ignorieren.</translation>
    </message>
    <message>
        <source>unexpected argument &apos;%1&apos;</source>
        <translation>unerwartetes Argument &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--%1: expected a number from %2 to %3, got &apos;%4&apos;</source>
        <translation>--%1: Zahl von %2 bis %3 erwartet, erhalten: &apos;%4&apos;</translation>
    </message>
    <message>
        <source>--size: expected WIDTHxHEIGHT such as 1280x800, got &apos;%1&apos;</source>
        <translation>--size: BREITExHÖHE wie 1280x800 erwartet, erhalten: &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--language: expected en or de, got &apos;%1&apos;</source>
        <translation>--language: en oder de erwartet, erhalten: &apos;%1&apos;</translation>
    </message>
    <message>
        <source>Start on a live rig: contact frames over UDP on this port (ADDRESS:PORT to listen beyond this machine).</source>
        <translation>Mit einem Live-Rig starten: Kontaktframes per UDP auf diesem Port (ADRESSE:PORT, um über diesen Rechner hinaus zu lauschen).</translation>
    </message>
    <message>
        <source>[address:]port</source>
        <translation>[adresse:]port</translation>
    </message>
    <message>
        <source>--listen: expected a port or ADDRESS:PORT such as 9871 or 0.0.0.0:9871, got &apos;%1&apos;</source>
        <translation>--listen: Port oder ADRESSE:PORT wie 9871 oder 0.0.0.0:9871 erwartet, erhalten: &apos;%1&apos;</translation>
    </message>
    <message>
        <source>Reaction time in seconds of the operator and of the person the router&apos;s predict nodes warn.</source>
        <translation>Reaktionszeit in Sekunden des Bedieners und der Person, die die Predict-Knoten des Routers warnen.</translation>
    </message>
    <message>
        <source>A gripper adapter, by name or as a semhap.gripper/1 file, whose model takes the place of the scene&apos;s grippers (default: the scene&apos;s own).</source>
        <translation>Ein Greifer-Adapter, als Name oder als semhap.gripper/1-Datei, dessen Modell an die Stelle der Greifer der Szene tritt (Standard: die eigenen der Szene).</translation>
    </message>
    <message>
        <source>gripper</source>
        <translation>Greifer</translation>
    </message>
    <message>
        <source>Open this study (a study database) in study mode.</source>
        <translation>Diese Studie (eine Studiendatenbank) im Studienmodus öffnen.</translation>
    </message>
    <message>
        <source>STUDY.db</source>
        <translation>STUDIE.db</translation>
    </message>
    <message>
        <source>With --study: the participant to work with.</source>
        <translation>Mit --study: die Versuchsperson, mit der gearbeitet wird.</translation>
    </message>
    <message>
        <source>id</source>
        <translation>id</translation>
    </message>
    <message>
        <source>With --participant: start their next step at once (for scripts and tests).</source>
        <translation>Mit --participant: ihren nächsten Schritt sofort starten (für Skripte und Tests).</translation>
    </message>
    <message>
        <source>--start-step: name the participant with --participant</source>
        <translation>--start-step: nennen Sie die Versuchsperson mit --participant</translation>
    </message>
    <message>
        <source>--participant: name the study with --study</source>
        <translation>--participant: nennen Sie die Studie mit --study</translation>
    </message>
    <message>
        <source>Who drives until you do: scripted, reactive or perceiving.</source>
        <translation>Wer steuert, bis Sie es tun: scripted, reactive oder perceiving.</translation>
    </message>
    <message>
        <source>Set a parameter of the perceiving operator&apos;s person (repeatable).</source>
        <translation>Einen Parameter der Person des wahrnehmenden Operators setzen (wiederholbar).</translation>
    </message>
    <message>
        <source>NAME=VALUE</source>
        <translation>NAME=WERT</translation>
    </message>
</context>
<context>
    <name>UndoActions</name>
    <message>
        <source>Redo</source>
        <translation>Wiederholen</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Rückgängig</translation>
    </message>
    <message>
        <source>Redo: %1</source>
        <translation>Wiederholen: %1</translation>
    </message>
    <message>
        <source>Undo: %1</source>
        <translation>Rückgängig: %1</translation>
    </message>
</context>
<context>
    <name>semhap::DevicesPanel</name>
    <message>
        <source>not bound</source>
        <translation>nicht zugeordnet</translation>
    </message>
    <message>
        <source>connected</source>
        <translation>verbunden</translation>
    </message>
    <message>
        <source>connecting</source>
        <translation>verbindet</translation>
    </message>
    <message>
        <source>disconnected</source>
        <translation>getrennt</translation>
    </message>
    <message>
        <source>%1 frames/s</source>
        <translation>%1 Frames/s</translation>
    </message>
    <message>
        <source>RTT %1 ms</source>
        <translation>RTT %1 ms</translation>
    </message>
    <message>
        <source>errors: %1</source>
        <translation>Fehler: %1</translation>
    </message>
    <message>
        <source>reconnects: %1</source>
        <translation>Neuverbindungen: %1</translation>
    </message>
    <message>
        <source>armed</source>
        <translation>freigegeben</translation>
    </message>
    <message>
        <source>disarmed</source>
        <translation>gesperrt</translation>
    </message>
    <message>
        <source>retrying: %1</source>
        <translation>neuer Versuch: %1</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Typ</translation>
    </message>
    <message>
        <source>URI</source>
        <translation>URI</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>Beschreibung</translation>
    </message>
    <message>
        <source>VID:PID</source>
        <translation>VID:PID</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Hinzufügen</translation>
    </message>
    <message>
        <source>Rescan</source>
        <translation>Neu suchen</translation>
    </message>
    <message>
        <source>Present devices</source>
        <translation>Vorhandene Geräte</translation>
    </message>
    <message>
        <source>Arm all</source>
        <translation>Alle freigeben</translation>
    </message>
    <message>
        <source>Disarm all</source>
        <translation>Alle sperren</translation>
    </message>
    <message>
        <source>Real bands start disarmed: they output nothing until armed.</source>
        <translation>Echte Armbänder starten gesperrt: Sie geben nichts aus, bis sie freigegeben werden.</translation>
    </message>
    <message>
        <source>Router devices</source>
        <translation>Router-Geräte</translation>
    </message>
    <message>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <source>The URI to drive %1: pick a present device or type one</source>
        <translation>Die URI, über die %1 angesteuert wird: ein vorhandenes Gerät wählen oder eine URI eingeben</translation>
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
        <source>Fall back to the virtual device virtual:%1; the run goes on</source>
        <translation>Auf das virtuelle Gerät virtual:%1 zurückschalten; der Lauf geht weiter</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>no transport</source>
        <translation>kein Transport</translation>
    </message>
    <message>
        <source>%1 of %2 armed</source>
        <translation>%1 von %2 freigegeben</translation>
    </message>
    <message>
        <source>e.g. udp:127.0.0.1:9000</source>
        <translation>z. B. udp:127.0.0.1:9000</translation>
    </message>
    <message>
        <source>Its hand is not in this scene.</source>
        <translation>Seine Hand ist nicht in dieser Szene.</translation>
    </message>
    <message>
        <source>latency %1 ms</source>
        <translation>Latenz %1 ms</translation>
    </message>
    <message>
        <source>%1 ch, %2 Hz (%3)</source>
        <translation>%1 Kan., %2 Hz (%3)</translation>
    </message>
    <message>
        <source>An address that cannot be discovered, such as a band on the network or a pseudo-terminal, in one of these forms:</source>
        <translation>Eine Adresse, die nicht automatisch gefunden werden kann, etwa ein Armband im Netzwerk oder ein Pseudo-Terminal, in einer dieser Formen:</translation>
    </message>
    <message>
        <source>Devices</source>
        <translation>Geräte</translation>
    </message>
</context>
<context>
    <name>semhap::DistinctivenessView</name>
    <message>
        <source>The band whose messages are compared</source>
        <translation>Das Band, dessen Nachrichten verglichen werden</translation>
    </message>
    <message numerus="yes">
        <source>%1 (%2): %n message(s)</source>
        <translation>
            <numerusform>%1 (%2): %n Nachricht</numerusform>
            <numerusform>%1 (%2): %n Nachrichten</numerusform>
        </translation>
    </message>
    <message>
        <source>The router has problems: once it compiles, this shows how far apart its messages feel on each band.</source>
        <translation>Der Router hat Fehler: Sobald er sich übersetzen lässt, steht hier, wie weit seine Nachrichten auf jedem Band auseinanderliegen.</translation>
    </message>
    <message>
        <source>Its patterns cannot be compared: %1</source>
        <translation>Seine Muster lassen sich nicht vergleichen: %1</translation>
    </message>
    <message>
        <source>No message plays on a band.</source>
        <translation>Keine Nachricht spielt auf einem Band.</translation>
    </message>
    <message>
        <source>%1 and %2: %3 JND apart</source>
        <translation>%1 und %2: %3 JND auseinander</translation>
    </message>
    <message>
        <source>Only %1 plays on this band: there is nothing here to take it for.</source>
        <translation>Nur %1 spielt auf diesem Band: Hier gibt es nichts, womit man sie verwechseln könnte.</translation>
    </message>
    <message>
        <source>At intensity %1 no two of these messages are closer than 1 JND: a person tells them apart.</source>
        <translation>Bei Intensität %1 liegen keine zwei dieser Nachrichten näher als 1 JND beieinander: Ein Mensch unterscheidet sie.</translation>
    </message>
    <message>
        <source>%1 and %2 (%3 JND)</source>
        <translation>%1 und %2 (%3 JND)</translation>
    </message>
    <message>
        <source>Confusable, under 1 JND: %1. A person will take one for the other.</source>
        <translation>Verwechselbar, unter 1 JND: %1. Ein Mensch wird die eine für die andere halten.</translation>
    </message>
</context>
<context>
    <name>semhap::Engine</name>
    <message>
        <source>nothing is loaded</source>
        <translation>nichts geladen</translation>
    </message>
    <message>
        <source>the router has no device &apos;%1&apos;</source>
        <translation>der Router hat kein Gerät &apos;%1&apos;</translation>
    </message>
    <message>
        <source>nothing runs that sends to devices</source>
        <translation>es läuft nichts, das an Geräte sendet</translation>
    </message>
    <message>
        <source>nothing runs that could be recorded</source>
        <translation>es läuft nichts, das aufgezeichnet werden könnte</translation>
    </message>
</context>
<context>
    <name>semhap::EventLogModel</name>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <source>Gripper</source>
        <translation>Greifer</translation>
    </message>
    <message>
        <source>Detector</source>
        <translation>Detektor</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Nachricht</translation>
    </message>
    <message>
        <source>Phase</source>
        <translation>Phase</translation>
    </message>
    <message>
        <source>Intensity</source>
        <translation>Intensität</translation>
    </message>
</context>
<context>
    <name>semhap::EventLogPanel</name>
    <message>
        <source>Follow</source>
        <translation>Folgen</translation>
    </message>
    <message>
        <source>Filter (detector, message, …)</source>
        <translation>Filter (Detektor, Nachricht, …)</translation>
    </message>
    <message>
        <source>Keep the newest event in view</source>
        <translation>Das neueste Ereignis sichtbar halten</translation>
    </message>
    <message>
        <source>All grippers</source>
        <translation>Alle Greifer</translation>
    </message>
    <message>
        <source>Left</source>
        <translation>Links</translation>
    </message>
    <message>
        <source>Right</source>
        <translation>Rechts</translation>
    </message>
    <message>
        <source>All categories</source>
        <translation>Alle Kategorien</translation>
    </message>
    <message>
        <source>Confirmation</source>
        <translation>Bestätigung</translation>
    </message>
    <message>
        <source>Exception</source>
        <translation>Ausnahme</translation>
    </message>
    <message>
        <source>All phases</source>
        <translation>Alle Phasen</translation>
    </message>
    <message>
        <source>Begin</source>
        <translation>Beginn</translation>
    </message>
    <message>
        <source>Update</source>
        <translation>Aktualisierung</translation>
    </message>
    <message>
        <source>End</source>
        <translation>Ende</translation>
    </message>
    <message>
        <source>Begin and end</source>
        <translation>Beginn und Ende</translation>
    </message>
    <message>
        <source>Events</source>
        <translation>Ereignisse</translation>
    </message>
</context>
<context>
    <name>semhap::HandDrive</name>
    <message>
        <source>Move the wrist away from you</source>
        <translation>Das Handgelenk von Ihnen weg bewegen</translation>
    </message>
    <message>
        <source>Move the wrist towards you</source>
        <translation>Das Handgelenk zu Ihnen hin bewegen</translation>
    </message>
    <message>
        <source>Move the wrist to the left</source>
        <translation>Das Handgelenk nach links bewegen</translation>
    </message>
    <message>
        <source>Move the wrist to the right</source>
        <translation>Das Handgelenk nach rechts bewegen</translation>
    </message>
    <message>
        <source>Raise the wrist</source>
        <translation>Das Handgelenk anheben</translation>
    </message>
    <message>
        <source>Lower the wrist (it stops on what is below)</source>
        <translation>Das Handgelenk senken (es hält auf dem an, was darunter liegt)</translation>
    </message>
    <message>
        <source>Turn the wrist left</source>
        <translation>Das Handgelenk nach links drehen</translation>
    </message>
    <message>
        <source>Turn the wrist right</source>
        <translation>Das Handgelenk nach rechts drehen</translation>
    </message>
    <message>
        <source>Close or open the grip</source>
        <translation>Den Griff schließen oder öffnen</translation>
    </message>
    <message>
        <source>Grip force up a step</source>
        <translation>Griffkraft eine Stufe höher</translation>
    </message>
    <message>
        <source>Grip force down a step</source>
        <translation>Griffkraft eine Stufe niedriger</translation>
    </message>
    <message>
        <source>Switch hand (scenes with two)</source>
        <translation>Hand wechseln (Szenen mit zwei Händen)</translation>
    </message>
    <message>
        <source>Hold: move at a quarter of the speed</source>
        <translation>Halten: mit einem Viertel der Geschwindigkeit bewegen</translation>
    </message>
</context>
<context>
    <name>semhap::HelpActions</name>
    <message>
        <source>Key map</source>
        <translation>Tastenbelegung</translation>
    </message>
    <message>
        <source>Every shortcut and drive key of the window</source>
        <translation>Alle Tastenkürzel und Steuertasten des Fensters</translation>
    </message>
    <message>
        <source>Documentation</source>
        <translation>Dokumentation</translation>
    </message>
    <message>
        <source>Open the studio&apos;s manual</source>
        <translation>Das Handbuch des Studios öffnen</translation>
    </message>
    <message>
        <source>The manual is not installed</source>
        <translation>Das Handbuch ist nicht installiert</translation>
    </message>
    <message>
        <source>Read docs/studio.md in semhap&apos;s sources.</source>
        <translation>Lesen Sie docs/studio.md in den Quellen von semhap.</translation>
    </message>
</context>
<context>
    <name>semhap::ImportProgress</name>
    <message>
        <source>Importing %1 into %2…</source>
        <translation>%1 wird nach %2 importiert …</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
</context>
<context>
    <name>semhap::KeyMapDialog</name>
    <message>
        <source>Key map</source>
        <translation>Tastenbelegung</translation>
    </message>
    <message>
        <source>Anywhere in the window</source>
        <translation>Überall im Fenster</translation>
    </message>
    <message>
        <source>In the viewport (click it first)</source>
        <translation>In der Szenenansicht (zuerst hineinklicken)</translation>
    </message>
    <message>
        <source>In the %1 panel</source>
        <translation>Im Bereich %1</translation>
    </message>
    <message>
        <source>Keys</source>
        <translation>Tasten</translation>
    </message>
    <message>
        <source>What they do</source>
        <translation>Was sie tun</translation>
    </message>
</context>
<context>
    <name>semhap::LiveRig</name>
    <message>
        <source>Live rig on %1
The rig draws its own scene.</source>
        <translation>Live-Rig auf %1
Das Rig zeichnet seine Szene selbst.</translation>
    </message>
</context>
<context>
    <name>semhap::LiveRigDialog</name>
    <message>
        <source>Listen for a live rig</source>
        <translation>Auf ein Live-Rig lauschen</translation>
    </message>
    <message>
        <source>any free port</source>
        <translation>beliebiger freier Port</translation>
    </message>
    <message>
        <source>Accept frames from other machines</source>
        <translation>Frames von anderen Rechnern annehmen</translation>
    </message>
    <message>
        <source>Listen on every network (0.0.0.0) instead of this machine only</source>
        <translation>In allen Netzen lauschen (0.0.0.0) statt nur auf diesem Rechner</translation>
    </message>
    <message>
        <source>UDP port:</source>
        <translation>UDP-Port:</translation>
    </message>
    <message>
        <source>Listen</source>
        <translation>Lauschen</translation>
    </message>
    <message>
        <source>PORT</source>
        <translation>PORT</translation>
    </message>
    <message>
        <source>&lt;p&gt;Send contact frames (one JSON object per datagram, or an array of them) to this port; they run through the detectors, the router &lt;b&gt;%1&lt;/b&gt; and the devices like the simulation&apos;s.&lt;/p&gt;&lt;p&gt;To try it: &lt;code&gt;scripts/send-frames.py resources/traces/demo.jsonl --port %2&lt;/code&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;Senden Sie Kontaktframes (ein JSON-Objekt pro Datagramm oder ein Array davon) an diesen Port; sie laufen wie die der Simulation durch die Detektoren, den Router &lt;b&gt;%1&lt;/b&gt; und die Geräte.&lt;/p&gt;&lt;p&gt;Zum Ausprobieren: &lt;code&gt;scripts/send-frames.py resources/traces/demo.jsonl --port %2&lt;/code&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Contact frames over UDP</source>
        <translation>Kontaktframes per UDP</translation>
    </message>
    <message>
        <source>A robot&apos;s Foxglove server</source>
        <translation>Der Foxglove-Server eines Roboters</translation>
    </message>
    <message>
        <source>the semhap.topics/1 map of its topics</source>
        <translation>die semhap.topics/1-Zuordnung seiner Topics</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Durchsuchen…</translation>
    </message>
    <message>
        <source>Topic map</source>
        <translation>Topic-Zuordnung</translation>
    </message>
    <message>
        <source>Topic maps (*.json);;All files (*)</source>
        <translation>Topic-Zuordnungen (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Server:</source>
        <translation>Server:</translation>
    </message>
    <message>
        <source>Topic map:</source>
        <translation>Topic-Zuordnung:</translation>
    </message>
    <message>
        <source>&lt;p&gt;The robot&apos;s topics become contact frames through the topic map, as a recording&apos;s do; they run through the detectors, the router &lt;b&gt;%1&lt;/b&gt; and the devices like the simulation&apos;s. When the robot restarts, the studio connects again.&lt;/p&gt;&lt;p&gt;On the robot: &lt;code&gt;ros2 launch foxglove_bridge foxglove_bridge_launch.xml&lt;/code&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;Die Topics des Roboters werden über die Topic-Zuordnung zu Kontaktframes, wie die einer Aufzeichnung; sie laufen wie die der Simulation durch die Detektoren, den Router &lt;b&gt;%1&lt;/b&gt; und die Geräte. Startet der Roboter neu, verbindet sich das Studio wieder.&lt;/p&gt;&lt;p&gt;Auf dem Roboter: &lt;code&gt;ros2 launch foxglove_bridge foxglove_bridge_launch.xml&lt;/code&gt;&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>semhap::MainWindow</name>
    <message>
        <source>Network pose input is off: %1</source>
        <translation>Posen-Eingabe über das Netzwerk ist aus: %1</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Starten</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <source>Could not reset the run</source>
        <translation>Der Lauf konnte nicht zurückgesetzt werden</translation>
    </message>
    <message>
        <source>Slower</source>
        <translation>Langsamer</translation>
    </message>
    <message>
        <source>Faster</source>
        <translation>Schneller</translation>
    </message>
    <message>
        <source>Real time</source>
        <translation>Echtzeit</translation>
    </message>
    <message>
        <source>Stop all</source>
        <translation>Alles stoppen</translation>
    </message>
    <message>
        <source>Pause the run and send every device to zero now (Esc, from anywhere)</source>
        <translation>Den Lauf anhalten und jedes Gerät sofort auf null setzen (Esc, von überall)</translation>
    </message>
    <message>
        <source>Stopped: every device was sent to zero.</source>
        <translation>Gestoppt: Jedes Gerät wurde auf null gesetzt.</translation>
    </message>
    <message>
        <source>Drive</source>
        <translation>Steuern</translation>
    </message>
    <message>
        <source>Take the grippers over from the scripted operator (Ctrl+T); any key or pose input does it too</source>
        <translation>Die Greifer vom skriptgesteuerten Bediener übernehmen (Strg+T); jede Taste und jede Posen-Eingabe tut das ebenfalls</translation>
    </message>
    <message>
        <source>Open scene…</source>
        <translation>Szene öffnen…</translation>
    </message>
    <message>
        <source>Open scene</source>
        <translation>Szene öffnen</translation>
    </message>
    <message>
        <source>MuJoCo scenes (*.xml)</source>
        <translation>MuJoCo-Szenen (*.xml)</translation>
    </message>
    <message>
        <source>Open router…</source>
        <translation>Router öffnen…</translation>
    </message>
    <message>
        <source>Open router</source>
        <translation>Router öffnen</translation>
    </message>
    <message>
        <source>semhap routers (*.json)</source>
        <translation>semhap-Router (*.json)</translation>
    </message>
    <message>
        <source>Preferences…</source>
        <translation>Einstellungen…</translation>
    </message>
    <message>
        <source>Reset layout</source>
        <translation>Layout zurücksetzen</translation>
    </message>
    <message>
        <source>Quit</source>
        <translation>Beenden</translation>
    </message>
    <message>
        <source>About semhap</source>
        <translation>Über semhap</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;semhap studio&lt;/b&gt; %1&lt;/p&gt;&lt;p&gt;Semantic haptic feedback for robot teleoperation: contact forces become confirmations and exceptions, routed to patterns on wristbands.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;semhap studio&lt;/b&gt; %1&lt;/p&gt;&lt;p&gt;Semantische haptische Rückmeldung für die Fernsteuerung von Robotern: Kontaktkräfte werden zu Bestätigungen und Ausnahmen, die als Muster auf Armbänder geleitet werden.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Could not connect %1 to %2</source>
        <translation>%1 konnte nicht mit %2 verbunden werden</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;Run</source>
        <translation>&amp;Lauf</translation>
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
        <source>Pause</source>
        <translation>Anhalten</translation>
    </message>
    <message>
        <source>The run reached its end. Reset to run it again.</source>
        <translation>Der Lauf ist zu Ende. Zum erneuten Starten zurücksetzen.</translation>
    </message>
    <message>
        <source>semhap studio — %1 · %2</source>
        <translation>semhap studio — %1 · %2</translation>
    </message>
    <message>
        <source>semhap studio</source>
        <translation>semhap studio</translation>
    </message>
    <message>
        <source>Could not load scene %1 with router %2</source>
        <translation>Szene %1 mit Router %2 konnte nicht geladen werden</translation>
    </message>
    <message>
        <source>The run is paused while you audition a pattern.</source>
        <translation>Der Lauf ist angehalten, während Sie ein Muster vorhören.</translation>
    </message>
    <message>
        <source>Record</source>
        <translation>Aufnehmen</translation>
    </message>
    <message>
        <source>Open session…</source>
        <translation>Sitzung öffnen…</translation>
    </message>
    <message>
        <source>Open session</source>
        <translation>Sitzung öffnen</translation>
    </message>
    <message>
        <source>Replay</source>
        <translation>Wiedergabe</translation>
    </message>
    <message>
        <source>Stop recording</source>
        <translation>Aufnahme beenden</translation>
    </message>
    <message>
        <source>Session saved to %1</source>
        <translation>Sitzung gespeichert unter %1</translation>
    </message>
    <message>
        <source>Could not start recording</source>
        <translation>Die Aufnahme konnte nicht gestartet werden</translation>
    </message>
    <message>
        <source>Could not open session %1</source>
        <translation>Sitzung %1 konnte nicht geöffnet werden</translation>
    </message>
    <message>
        <source>semhap studio — replay of %1</source>
        <translation>semhap studio — Wiedergabe von %1</translation>
    </message>
    <message>
        <source>Could not re-route the session</source>
        <translation>Die Sitzung konnte nicht neu geleitet werden</translation>
    </message>
    <message>
        <source>Could not listen on udp:%1:%2</source>
        <translation>Konnte nicht auf udp:%1:%2 lauschen</translation>
    </message>
    <message>
        <source>Listening for a live rig on %1</source>
        <translation>Lausche auf ein Live-Rig auf %1</translation>
    </message>
    <message>
        <source>Listen for a live rig…</source>
        <translation>Auf ein Live-Rig lauschen…</translation>
    </message>
    <message>
        <source>Run another program&apos;s contact frames, sent over UDP, instead of the scene (Ctrl+L)</source>
        <translation>Die per UDP gesendeten Kontaktframes eines anderen Programms statt der Szene verarbeiten (Strg+L)</translation>
    </message>
    <message>
        <source>semhap studio — live rig on %1 · %2</source>
        <translation>semhap studio — Live-Rig auf %1 · %2</translation>
    </message>
    <message>
        <source>Record the run into a new session in the sessions folder (Ctrl+Shift+R); again to stop</source>
        <translation>Den Lauf in eine neue Sitzung im Sitzungsordner aufzeichnen (Strg+Umschalt+R); erneut zum Beenden</translation>
    </message>
    <message numerus="yes">
        <source>%n row(s) of the session break the stream rules and were skipped (semhap replay lists them)</source>
        <translation>
            <numerusform>%n Zeile der Sitzung verletzt die Regeln der Datenströme und wurde übersprungen (semhap replay nennt sie)</numerusform>
            <numerusform>%n Zeilen der Sitzung verletzen die Regeln der Datenströme und wurden übersprungen (semhap replay nennt sie)</numerusform>
        </translation>
    </message>
    <message>
        <source>No gamepad connected</source>
        <translation>Kein Gamepad verbunden</translation>
    </message>
    <message>
        <source>Gamepad: %1</source>
        <translation>Gamepad: %1</translation>
    </message>
    <message>
        <source>Gamepads are off: %1</source>
        <translation>Gamepads sind aus: %1</translation>
    </message>
    <message>
        <source>&amp;Camera</source>
        <translation>&amp;Kamera</translation>
    </message>
    <message>
        <source>3D mouse: %1</source>
        <translation>3D-Maus: %1</translation>
    </message>
    <message>
        <source>3D mouse disconnected: the wrist stopped</source>
        <translation>3D-Maus getrennt: das Handgelenk steht</translation>
    </message>
    <message>
        <source>The router editor keeps your edits, which are not what runs now: Apply runs them.</source>
        <translation>Der Router-Editor behält Ihre Änderungen, die gerade nicht laufen: Anwenden startet sie.</translation>
    </message>
    <message>
        <source>Task done
The pile was finished after %1 s.
Carry on with the refilled box, or reset (%2) to start over.</source>
        <translation>Aufgabe erledigt
Der Stapel war nach %1 s abgearbeitet.
Machen Sie mit der wieder gefüllten Kiste weiter, oder setzen Sie zurück (%2), um neu zu beginnen.</translation>
    </message>
    <message>
        <source>%1 with %2</source>
        <translation>%1 mit %2</translation>
    </message>
    <message>
        <source>Could not load scene %1 with gripper %2 and router %3</source>
        <translation>Szene %1 mit Greifer %2 und Router %3 konnte nicht geladen werden</translation>
    </message>
    <message>
        <source>Gripper</source>
        <translation>Greifer</translation>
    </message>
    <message>
        <source>Could not load router %1</source>
        <translation>Router %1 konnte nicht geladen werden</translation>
    </message>
    <message>
        <source>Could not load scene %1</source>
        <translation>Szene %1 konnte nicht geladen werden</translation>
    </message>
    <message>
        <source>Could not load gripper %1 into scene %2</source>
        <translation>Greifer %1 konnte nicht in Szene %2 geladen werden</translation>
    </message>
    <message>
        <source>%1 runs with its own router, %2</source>
        <translation>%1 läuft mit seinem eigenen Router, %2</translation>
    </message>
    <message>
        <source>%1 has a router of its own, %2: pick it under Router</source>
        <translation>%1 hat einen eigenen Router, %2: wählen Sie ihn unter Router</translation>
    </message>
    <message>
        <source>semhap sessions and robot recordings (*.db *.mcap);;semhap sessions (*.db);;Robot recordings, rosbag2 in MCAP (*.mcap);;All files (*)</source>
        <translation>semhap-Sitzungen und Roboteraufzeichnungen (*.db *.mcap);;semhap-Sitzungen (*.db);;Roboteraufzeichnungen, rosbag2 in MCAP (*.mcap);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Topic map of %1</source>
        <translation>Topic-Zuordnung für %1</translation>
    </message>
    <message>
        <source>Topic maps (*.json);;All files (*)</source>
        <translation>Topic-Zuordnungen (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Could not import %1</source>
        <translation>%1 konnte nicht importiert werden</translation>
    </message>
    <message>
        <source>Import of %1 cancelled</source>
        <translation>Import von %1 abgebrochen</translation>
    </message>
    <message numerus="yes">
        <source>Imported %1: %n frame(s) into %2</source>
        <translation>
            <numerusform>%1 importiert: %n Frame nach %2</numerusform>
            <numerusform>%1 importiert: %n Frames nach %2</numerusform>
        </translation>
    </message>
    <message>
        <source>Publishing to Foxglove at %1</source>
        <translation>Veröffentlicht für Foxglove unter %1</translation>
    </message>
    <message>
        <source>Cannot publish to Foxglove on port %1: %2</source>
        <translation>Veröffentlichen für Foxglove auf Port %1 nicht möglich: %2</translation>
    </message>
    <message>
        <source>Export session…</source>
        <translation>Sitzung exportieren…</translation>
    </message>
    <message>
        <source>Write the session replayed, or one you pick, as XDF for labs synchronised by the Lab Streaming Layer or as MCAP for Foxglove, PlotJuggler and Rerun</source>
        <translation>Die wiedergegebene oder eine gewählte Sitzung als XDF für Labore, die mit dem Lab Streaming Layer synchronisieren, oder als MCAP für Foxglove, PlotJuggler und Rerun schreiben</translation>
    </message>
    <message>
        <source>Session to export</source>
        <translation>Zu exportierende Sitzung</translation>
    </message>
    <message>
        <source>semhap sessions (*.db);;All files (*)</source>
        <translation>semhap-Sitzungen (*.db);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Exporting %1…</source>
        <translation>%1 wird exportiert…</translation>
    </message>
    <message>
        <source>Could not export the session</source>
        <translation>Die Sitzung konnte nicht exportiert werden</translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation>%1 exportiert</translation>
    </message>
    <message>
        <source>Session exported</source>
        <translation>Sitzung exportiert</translation>
    </message>
</context>
<context>
    <name>semhap::ManualWindow</name>
    <message>
        <source>semhap studio manual</source>
        <translation>Handbuch von semhap studio</translation>
    </message>
    <message>
        <source>Back (Alt+Left)</source>
        <translation>Zurück (Alt+Links)</translation>
    </message>
    <message>
        <source>Forward (Alt+Right)</source>
        <translation>Vor (Alt+Rechts)</translation>
    </message>
    <message>
        <source>The studio&apos;s manual</source>
        <translation>Das Handbuch des Studios</translation>
    </message>
    <message>
        <source>Search the page (Ctrl+F)</source>
        <translation>Auf der Seite suchen (Strg+F)</translation>
    </message>
    <message>
        <source>Not found</source>
        <translation>Nicht gefunden</translation>
    </message>
    <message>
        <source>semhap studio manual — %1</source>
        <translation>Handbuch von semhap studio — %1</translation>
    </message>
</context>
<context>
    <name>semhap::MetricSpec</name>
    <message>
        <source>Plugs inserted</source>
        <translation>Stecker eingesteckt</translation>
    </message>
    <message>
        <source>Plugs seated in the port.</source>
        <translation>In die Buchse gesteckte Stecker.</translation>
    </message>
    <message>
        <source>Time to insert</source>
        <translation>Zeit zum Einstecken</translation>
    </message>
    <message>
        <source>The mean time from picking a plug up to seating it.</source>
        <translation>Die mittlere Zeit vom Aufnehmen eines Steckers bis zum Stecken.</translation>
    </message>
    <message>
        <source>Collisions with the port</source>
        <translation>Kollisionen mit der Buchse</translation>
    </message>
    <message>
        <source>Times the plug pushed on the port&apos;s face beside the opening.</source>
        <translation>Wie oft der Stecker neben der Öffnung auf die Buchse drückte.</translation>
    </message>
    <message>
        <source>Peak insertion force</source>
        <translation>Höchste Steckkraft</translation>
    </message>
    <message>
        <source>The highest force on the port during the run.</source>
        <translation>Die höchste Kraft auf die Buchse während des Laufs.</translation>
    </message>
    <message>
        <source>Plug pick-ups</source>
        <translation>Stecker aufgenommen</translation>
    </message>
    <message>
        <source>Times a plug was lifted from where it was laid out.</source>
        <translation>Wie oft ein Stecker von seinem Platz angehoben wurde.</translation>
    </message>
    <message>
        <source>Plugs dropped</source>
        <translation>Stecker fallen gelassen</translation>
    </message>
    <message>
        <source>Plugs let go of after a pick-up without being seated.</source>
        <translation>Stecker, die nach dem Aufnehmen losgelassen wurden, ohne zu stecken.</translation>
    </message>
    <message>
        <source>Cues taken in</source>
        <translation>Wahrgenommene Signale</translation>
    </message>
    <message>
        <source>Cues the perceiving operator felt on a band or saw on the overlay.</source>
        <translation>Signale, die der wahrnehmende Bediener an einem Armband gespürt oder in der Einblendung gesehen hat.</translation>
    </message>
    <message>
        <source>Cues misread</source>
        <translation>Verwechselte Signale</translation>
    </message>
    <message>
        <source>Cues the perceiving operator took for a message of the other meaning: a warning for a confirmation, or the other way round.</source>
        <translation>Signale, die der wahrnehmende Bediener für eine Nachricht der anderen Bedeutung hielt: eine Warnung für eine Bestätigung oder umgekehrt.</translation>
    </message>
    <message>
        <source>Warnings ignored</source>
        <translation>Übergangene Warnungen</translation>
    </message>
    <message>
        <source>Warnings the perceiving operator felt and did not answer, for how seldom that hand&apos;s warnings had been right.</source>
        <translation>Warnungen, die der wahrnehmende Bediener spürte und nicht beantwortete, weil die Warnungen dieser Hand selten gestimmt hatten.</translation>
    </message>
    <message>
        <source>Left reliance</source>
        <translation>Vertrauen links</translation>
    </message>
    <message>
        <source>The share of the left hand&apos;s warnings the perceiving operator answers now.</source>
        <translation>Der Anteil der Warnungen der linken Hand, die der wahrnehmende Bediener jetzt beantwortet.</translation>
    </message>
    <message>
        <source>Right reliance</source>
        <translation>Vertrauen rechts</translation>
    </message>
    <message>
        <source>The share of the right hand&apos;s warnings the perceiving operator answers now.</source>
        <translation>Der Anteil der Warnungen der rechten Hand, die der wahrnehmende Bediener jetzt beantwortet.</translation>
    </message>
    <message>
        <source>Simulated time</source>
        <translation>Simulierte Zeit</translation>
    </message>
    <message>
        <source>Simulated time so far.</source>
        <translation>Bisher simulierte Zeit.</translation>
    </message>
    <message>
        <source>Wall time</source>
        <translation>Reale Zeit</translation>
    </message>
    <message>
        <source>Real time so far.</source>
        <translation>Bisher vergangene echte Zeit.</translation>
    </message>
    <message>
        <source>Real-time factor</source>
        <translation>Echtzeitfaktor</translation>
    </message>
    <message>
        <source>Simulated seconds per real second.</source>
        <translation>Simulierte Sekunden pro echter Sekunde.</translation>
    </message>
    <message>
        <source>Scene</source>
        <translation>Szene</translation>
    </message>
    <message>
        <source>The task that runs.</source>
        <translation>Die laufende Aufgabe.</translation>
    </message>
    <message>
        <source>Router</source>
        <translation>Router</translation>
    </message>
    <message>
        <source>The router the run was loaded with.</source>
        <translation>Der Router, mit dem der Lauf geladen wurde.</translation>
    </message>
    <message>
        <source>Operator</source>
        <translation>Bediener</translation>
    </message>
    <message>
        <source>Who drives the grippers when you do not.</source>
        <translation>Wer die Greifer steuert, wenn Sie es nicht tun.</translation>
    </message>
    <message>
        <source>Seed</source>
        <translation>Startwert</translation>
    </message>
    <message>
        <source>The seed of the operator and of a laid-out scene.</source>
        <translation>Der Startwert des Bedieners und einer ausgelegten Szene.</translation>
    </message>
    <message>
        <source>Completion time</source>
        <translation>Zeit bis zum Abschluss</translation>
    </message>
    <message>
        <source>When the pile was first finished: every cube transferred or broken (box_and_block).</source>
        <translation>Wann der Stapel zuerst abgearbeitet war: jeder Würfel übertragen oder zerbrochen (box_and_block).</translation>
    </message>
    <message>
        <source>Cubes transferred</source>
        <translation>Transportierte Würfel</translation>
    </message>
    <message>
        <source>Cubes that arrived where the task wants them, once per trip.</source>
        <translation>Würfel, die dort ankamen, wo die Aufgabe sie haben will, einmal je Weg.</translation>
    </message>
    <message>
        <source>Cubes broken</source>
        <translation>Zerbrochene Würfel</translation>
    </message>
    <message>
        <source>Cubes that fractured under the fingertips.</source>
        <translation>Würfel, die unter den Fingerspitzen zerbrachen.</translation>
    </message>
    <message>
        <source>Cubes dropped (slipped out)</source>
        <translation>Verlorene Würfel (herausgerutscht)</translation>
    </message>
    <message>
        <source>Grasps that ended while the hand still gripped, after a lift: the cube slipped out.</source>
        <translation>Griffe, die endeten, während die Hand noch zugriff, nach einem Anheben: Der Würfel rutschte heraus.</translation>
    </message>
    <message>
        <source>Grasps</source>
        <translation>Griffe</translation>
    </message>
    <message>
        <source>Grasps begun.</source>
        <translation>Begonnene Griffe.</translation>
    </message>
    <message>
        <source>Grasps per transfer</source>
        <translation>Griffe pro Transport</translation>
    </message>
    <message>
        <source>Grasps per cube transferred: 1 is one grasp for each.</source>
        <translation>Griffe je übertragenem Würfel: 1 ist ein Griff für jeden.</translation>
    </message>
    <message>
        <source>Average grasp force</source>
        <translation>Mittlere Griffkraft</translation>
    </message>
    <message>
        <source>The mean force of both fingertips over every moment of every grasp.</source>
        <translation>Die mittlere Kraft beider Fingerspitzen über jeden Moment jedes Griffs.</translation>
    </message>
    <message>
        <source>Average peak grasp force</source>
        <translation>Mittlere Spitzen-Griffkraft</translation>
    </message>
    <message>
        <source>The mean over grasps of the highest force during each.</source>
        <translation>Der Mittelwert über die Griffe der jeweils höchsten Kraft.</translation>
    </message>
    <message>
        <source>Warning lead time</source>
        <translation>Vorwarnzeit</translation>
    </message>
    <message>
        <source>How long before a break its warning was first felt, on average.</source>
        <translation>Wie lange vor einem Bruch seine Warnung zuerst gespürt wurde, im Mittel.</translation>
    </message>
    <message>
        <source>Breaks warned</source>
        <translation>Vorgewarnte Brüche</translation>
    </message>
    <message>
        <source>The share of breaks a felt warning came before.</source>
        <translation>Der Anteil der Brüche, denen eine gespürte Warnung vorausging.</translation>
    </message>
    <message>
        <source>Breaks warned in time</source>
        <translation>Rechtzeitig vorgewarnte Brüche</translation>
    </message>
    <message>
        <source>The share of breaks warned at least a reaction time before: the warnings a person could act on.</source>
        <translation>Der Anteil der Brüche, die mindestens eine Reaktionszeit vorher gewarnt wurden: die Warnungen, auf die ein Mensch handeln konnte.</translation>
    </message>
    <message>
        <source>Containers dropped</source>
        <translation>Fallen gelassene Behälter</translation>
    </message>
    <message>
        <source>Times the held container left the left fingertips and fell (bimanual).</source>
        <translation>Wie oft der gehaltene Behälter die linken Fingerspitzen verließ und fiel (beidhändig).</translation>
    </message>
    <message>
        <source>Drop warning lead time</source>
        <translation>Vorwarnzeit vor Abstürzen</translation>
    </message>
    <message>
        <source>How long before a container drop its warning was first felt, on average (bimanual).</source>
        <translation>Wie lange vor einem Fall des Behälters seine Warnung zuerst gespürt wurde, im Mittel (beidhändig).</translation>
    </message>
    <message>
        <source>Drops warned</source>
        <translation>Vorgewarnte Abstürze</translation>
    </message>
    <message>
        <source>The share of container drops a felt warning came before (bimanual).</source>
        <translation>Der Anteil der Behälterfälle, denen eine gespürte Warnung vorausging (beidhändig).</translation>
    </message>
    <message>
        <source>Drops warned in time</source>
        <translation>Rechtzeitig vorgewarnte Abstürze</translation>
    </message>
    <message>
        <source>The share of container drops warned at least a reaction time before (bimanual).</source>
        <translation>Der Anteil der Behälterfälle, die mindestens eine Reaktionszeit vorher gewarnt wurden (beidhändig).</translation>
    </message>
    <message>
        <source>Containers set down</source>
        <translation>Abgestellte Behälter</translation>
    </message>
    <message>
        <source>Times the holding hand set the full container down on its base to be emptied (bimanual).</source>
        <translation>Wie oft die haltende Hand den vollen Behälter zum Leeren auf seinen Sockel stellte (beidhändig).</translation>
    </message>
    <message>
        <source>Transfers per container cycle</source>
        <translation>Transporte pro Behälterzyklus</translation>
    </message>
    <message>
        <source>Cubes transferred per container cycle, which a drop or a set-down ends (bimanual).</source>
        <translation>Übertragene Würfel je Behälterzyklus, den ein Fallen oder Abstellen beendet (beidhändig).</translation>
    </message>
    <message>
        <source>Confirmations felt per grasp</source>
        <translation>Gespürte Bestätigungen je Griff</translation>
    </message>
    <message>
        <source>Confirmations felt per real grasp: 1 is one per grasp, more is chatter, 0 without feedback.</source>
        <translation>Gespürte Bestätigungen je echtem Griff: 1 ist eine je Griff, mehr ist Flattern, 0 ohne Rückmeldung.</translation>
    </message>
    <message>
        <source>Slip episodes</source>
        <translation>Rutschphasen</translation>
    </message>
    <message>
        <source>Times the container slid in the left fingertips (bimanual).</source>
        <translation>Wie oft der Behälter in den linken Fingerspitzen rutschte (beidhändig).</translation>
    </message>
    <message>
        <source>Warnings felt per slip episode</source>
        <translation>Gespürte Warnungen je Rutschphase</translation>
    </message>
    <message>
        <source>Warnings felt on the left hand per slip: above 1, warnings came that no slip answered (bimanual).</source>
        <translation>Gespürte Warnungen an der linken Hand je Rutschen: über 1 kamen Warnungen, denen kein Rutschen entsprach (beidhändig).</translation>
    </message>
    <message>
        <source>Breaks warned by onset</source>
        <translation>Brüche mit rechtzeitig begonnener Warnung</translation>
    </message>
    <message>
        <source>The share of breaks whose warning began within the horizon before, in time to act: a warning on all along does not count.</source>
        <translation>Der Anteil der Brüche, deren Warnung innerhalb des Horizonts davor begann, rechtzeitig zum Handeln: Eine Warnung, die schon die ganze Zeit lief, zählt nicht.</translation>
    </message>
    <message>
        <source>Right warnings borne out</source>
        <translation>Bestätigte Warnungen rechts</translation>
    </message>
    <message>
        <source>The share of the right hand&apos;s warnings a break, or the grip crossing the break line, followed within the horizon: the rest were false alarms.</source>
        <translation>Der Anteil der Warnungen der rechten Hand, denen innerhalb des Horizonts ein Bruch oder ein Überschreiten der Bruchgrenze folgte: Die übrigen waren Fehlalarme.</translation>
    </message>
    <message>
        <source>Right warning duty</source>
        <translation>Warnungsanteil rechts</translation>
    </message>
    <message>
        <source>The share of grasping time a warning was felt on the right hand.</source>
        <translation>Der Anteil der Greifzeit, in dem an der rechten Hand eine Warnung zu spüren war.</translation>
    </message>
    <message>
        <source>Drops warned by onset</source>
        <translation>Stürze mit rechtzeitig begonnener Warnung</translation>
    </message>
    <message>
        <source>The share of container drops whose warning began within the horizon before, in time to act (bimanual).</source>
        <translation>Der Anteil der Behälterstürze, deren Warnung innerhalb des Horizonts davor begann, rechtzeitig zum Handeln (beidhändig).</translation>
    </message>
    <message>
        <source>Left warnings borne out</source>
        <translation>Bestätigte Warnungen links</translation>
    </message>
    <message>
        <source>The share of the left hand&apos;s warnings a drop or a slip followed within the horizon: the rest were false alarms (bimanual).</source>
        <translation>Der Anteil der Warnungen der linken Hand, denen innerhalb des Horizonts ein Sturz oder ein Rutschen folgte: Die übrigen waren Fehlalarme (beidhändig).</translation>
    </message>
    <message>
        <source>Left warning duty</source>
        <translation>Warnungsanteil links</translation>
    </message>
    <message>
        <source>The share of the time the container was held that a warning was felt (bimanual).</source>
        <translation>Der Anteil der Haltezeit des Behälters, in dem eine Warnung zu spüren war (beidhändig).</translation>
    </message>
    <message>
        <source>Cube box refills</source>
        <translation>Nachfüllungen der Würfelkiste</translation>
    </message>
    <message>
        <source>Times the cube box was refilled.</source>
        <translation>Wie oft die Würfelkiste nachgefüllt wurde.</translation>
    </message>
    <message>
        <source>Area cleaned (plates)</source>
        <translation>Gereinigte Fläche (Teller)</translation>
    </message>
    <message>
        <source>Cells cleaned, in plates&apos; worth: above 1 when more than a plate was cleaned.</source>
        <translation>Gereinigte Felder, in Tellern gerechnet: über 1, wenn mehr als ein Teller gereinigt wurde.</translation>
    </message>
    <message>
        <source>Time to clean</source>
        <translation>Zeit bis sauber</translation>
    </message>
    <message>
        <source>When every cell of the first plate was first clean.</source>
        <translation>Wann jedes Feld des ersten Tellers zuerst sauber war.</translation>
    </message>
    <message>
        <source>Plates cleaned</source>
        <translation>Teller gereinigt</translation>
    </message>
    <message>
        <source>Times every cell of a plate was clean at once.</source>
        <translation>Wie oft jedes Feld eines Tellers zugleich sauber war.</translation>
    </message>
    <message>
        <source>Plates broken</source>
        <translation>Teller zerbrochen</translation>
    </message>
    <message>
        <source>Plates broken by pressing above 40 N.</source>
        <translation>Teller, die durch Drücken über 40 N zerbrachen.</translation>
    </message>
    <message>
        <source>Peak force</source>
        <translation>Spitzenkraft</translation>
    </message>
    <message>
        <source>The highest press of the sponge on the plate.</source>
        <translation>Der stärkste Druck des Schwamms auf den Teller.</translation>
    </message>
    <message>
        <source>Time above the safe force</source>
        <translation>Zeit über der sicheren Kraft</translation>
    </message>
    <message>
        <source>The time the press was above the safe 25 N.</source>
        <translation>Die Zeit, in der der Druck über den sicheren 25 N lag.</translation>
    </message>
    <message>
        <source>Average press force</source>
        <translation>Mittlere Andruckkraft</translation>
    </message>
    <message>
        <source>The mean press while the sponge pressed on the plate.</source>
        <translation>Der mittlere Druck, während der Schwamm auf den Teller drückte.</translation>
    </message>
    <message>
        <source>Warnings felt</source>
        <translation>Gefühlte Warnungen</translation>
    </message>
    <message>
        <source>Warnings felt on the wiping hand.</source>
        <translation>An der wischenden Hand gespürte Warnungen.</translation>
    </message>
    <message>
        <source>Sponge stiffened at</source>
        <translation>Schwamm versteift bei</translation>
    </message>
    <message>
        <source>When the sponge&apos;s holder stiffened.</source>
        <translation>Wann die Halterung des Schwamms steif wurde.</translation>
    </message>
    <message>
        <source>Blocks stacked</source>
        <translation>Gestapelte Klötze</translation>
    </message>
    <message>
        <source>Levels the placements added to the tower.</source>
        <translation>Ebenen, die das Absetzen dem Turm hinzufügte.</translation>
    </message>
    <message>
        <source>Towers built</source>
        <translation>Gebaute Türme</translation>
    </message>
    <message>
        <source>Towers stacked five blocks high.</source>
        <translation>Türme, fünf Klötze hoch gestapelt.</translation>
    </message>
    <message>
        <source>Tallest tower</source>
        <translation>Höchster Turm</translation>
    </message>
    <message>
        <source>The most levels the tower had at once.</source>
        <translation>Die meisten Ebenen, die der Turm auf einmal hatte.</translation>
    </message>
    <message>
        <source>Topples</source>
        <translation>Einstürze</translation>
    </message>
    <message>
        <source>Times the tower lost levels without a block being taken off it.</source>
        <translation>Wie oft der Turm Ebenen verlor, ohne dass ein Klotz abgenommen wurde.</translation>
    </message>
    <message>
        <source>Blocks dropped</source>
        <translation>Fallen gelassene Klötze</translation>
    </message>
    <message>
        <source>Lifted blocks let go of anywhere but on top of the tower.</source>
        <translation>Angehobene Klötze, die anderswo als oben auf dem Turm losgelassen wurden.</translation>
    </message>
    <message>
        <source>Time per level</source>
        <translation>Zeit je Ebene</translation>
    </message>
    <message>
        <source>The mean time from lifting a block to the level it adds.</source>
        <translation>Die mittlere Zeit vom Anheben eines Klotzes bis zu der Ebene, die er hinzufügt.</translation>
    </message>
</context>
<context>
    <name>semhap::MetricsPanel</name>
    <message>
        <source>No metrics yet: they appear while a task runs.</source>
        <translation>Noch keine Metriken: Sie erscheinen, während eine Aufgabe läuft.</translation>
    </message>
    <message>
        <source>n/a</source>
        <translation>k. A.</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <source>no</source>
        <translation>nein</translation>
    </message>
    <message>
        <source>%1×</source>
        <translation>%1×</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>%1 N</source>
        <translation>%1 N</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>a count</source>
        <translation>einer Anzahl</translation>
    </message>
    <message>
        <source>a ratio</source>
        <translation>einem Verhältnis</translation>
    </message>
    <message>
        <source>times real time</source>
        <translation>Vielfachen der Echtzeit</translation>
    </message>
    <message>
        <source>seconds of simulated time</source>
        <translation>Sekunden simulierter Zeit</translation>
    </message>
    <message>
        <source>newtons (N)</source>
        <translation>Newton (N)</translation>
    </message>
    <message>
        <source>a share, 0 to 100 %</source>
        <translation>einem Anteil, 0 bis 100 %</translation>
    </message>
    <message>
        <source>%1
In exports: %2</source>
        <translation>%1
In Exporten: %2</translation>
    </message>
    <message>
        <source>%1
In %2; in exports: %3</source>
        <translation>%1
In %2; in Exporten: %3</translation>
    </message>
    <message>
        <source>Higher is better.</source>
        <translation>Höher ist besser.</translation>
    </message>
    <message>
        <source>Lower is better.</source>
        <translation>Niedriger ist besser.</translation>
    </message>
    <message>
        <source>Task metrics</source>
        <translation>Aufgabenmetriken</translation>
    </message>
</context>
<context>
    <name>semhap::NodeInspector</name>
    <message>
        <source>Pattern</source>
        <translation>Muster</translation>
    </message>
    <message>
        <source>Track %1</source>
        <translation>Spur %1</translation>
    </message>
    <message>
        <source>Waveform</source>
        <translation>Wellenform</translation>
    </message>
    <message>
        <source>Select a node in the tree</source>
        <translation>Einen Knoten im Baum auswählen</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>Beschreibung</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Channels</source>
        <translation>Kanäle</translation>
    </message>
    <message>
        <source>* drives every channel of the model</source>
        <translation>* steuert jeden Kanal des Modells an</translation>
    </message>
    <message>
        <source>Changing the type to a combinator keeps this waveform as its input</source>
        <translation>Wird der Typ in einen Kombinator geändert, bleibt diese Wellenform als dessen Eingang erhalten</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Typ</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Gain</source>
        <translation>Verstärkung</translation>
    </message>
    <message>
        <source>Offset</source>
        <translation>Versatz</translation>
    </message>
    <message>
        <source>To</source>
        <translation>Zielwert</translation>
    </message>
    <message>
        <source>Amplitude</source>
        <translation>Amplitude</translation>
    </message>
    <message>
        <source>Duty</source>
        <translation>Tastgrad</translation>
    </message>
    <message>
        <source>High</source>
        <translation>Hochpegel</translation>
    </message>
    <message>
        <source>Low</source>
        <translation>Tiefpegel</translation>
    </message>
    <message>
        <source>Divide by</source>
        <translation>Teilen durch</translation>
    </message>
    <message>
        <source>Minimum</source>
        <translation>Minimum</translation>
    </message>
    <message>
        <source>Maximum</source>
        <translation>Maximum</translation>
    </message>
    <message>
        <source>Its inputs are the children in the tree.</source>
        <translation>Seine Eingänge sind die untergeordneten Knoten im Baum.</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>Punkte</translation>
    </message>
    <message>
        <source>Frequency</source>
        <translation>Frequenz</translation>
    </message>
    <message>
        <source>Phase</source>
        <translation>Phase</translation>
    </message>
    <message>
        <source>Rate</source>
        <translation>Rate</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>Breite</translation>
    </message>
    <message>
        <source>Curve</source>
        <translation>Kurve</translation>
    </message>
    <message>
        <source>Starts from</source>
        <translation>Beginnt bei</translation>
    </message>
</context>
<context>
    <name>semhap::NotesPage</name>
    <message>
        <source>Notes</source>
        <translation>Notizen</translation>
    </message>
</context>
<context>
    <name>semhap::NumberEdit</name>
    <message>
        <source>A fixed value, or a live parameter of the pattern</source>
        <translation>Ein fester Wert oder ein Live-Parameter des Musters</translation>
    </message>
    <message>
        <source>× </source>
        <translation>× </translation>
    </message>
    <message>
        <source>Gain: the value is gain × parameter + offset</source>
        <translation>Verstärkung: Der Wert ist Verstärkung × Parameter + Versatz</translation>
    </message>
    <message>
        <source>+ </source>
        <translation>+ </translation>
    </message>
    <message>
        <source>Offset: the value is gain × parameter + offset</source>
        <translation>Versatz: Der Wert ist Verstärkung × Parameter + Versatz</translation>
    </message>
    <message>
        <source>through a curve (edit it in the JSON tab)</source>
        <translation>über eine Kurve (im Reiter JSON bearbeiten)</translation>
    </message>
    <message>
        <source>value</source>
        <translation>Wert</translation>
    </message>
</context>
<context>
    <name>semhap::ParamForm</name>
    <message>
        <source>(none)</source>
        <translation>(keine)</translation>
    </message>
    <message>
        <source>(any)</source>
        <translation>(beliebig)</translation>
    </message>
    <message>
        <source>(automatic)</source>
        <translation>(automatisch)</translation>
    </message>
    <message>
        <source>(default: %1)</source>
        <translation>(Standard: %1)</translation>
    </message>
    <message>
        <source>(default)</source>
        <translation>(Standard)</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Not a parameter of this node: clear it</source>
        <translation>Kein Parameter dieses Knotens: bitte leeren</translation>
    </message>
    <message>
        <source>current value</source>
        <translation>aktueller Wert</translation>
    </message>
    <message>
        <source>peak since begin</source>
        <translation>Spitzenwert seit Beginn</translation>
    </message>
    <message>
        <source>fixed value</source>
        <translation>fester Wert</translation>
    </message>
    <message>
        <source>Where the envelope starts: the track&apos;s value when it began, its peak, or a fixed value</source>
        <translation>Wo die Hüllkurve beginnt: beim Wert der Spur zu ihrem Beginn, bei ihrem Spitzenwert oder bei einem festen Wert</translation>
    </message>
    <message>
        <source>Start value</source>
        <translation>Anfangswert</translation>
    </message>
    <message>
        <source>Not understood; nothing was changed</source>
        <translation>Nicht verstanden; nichts wurde geändert</translation>
    </message>
</context>
<context>
    <name>semhap::PatternAuditioner</name>
    <message>
        <source>There is no device to play on.</source>
        <translation>Es gibt kein Gerät zum Abspielen.</translation>
    </message>
</context>
<context>
    <name>semhap::PatternDocument</name>
    <message>
        <source>Edit %1</source>
        <translation>%1 bearbeiten</translation>
    </message>
</context>
<context>
    <name>semhap::PatternPreview</name>
    <message>
        <source>all channels</source>
        <translation>alle Kanäle</translation>
    </message>
    <message>
        <source>time since begin (s)</source>
        <translation>Zeit seit Beginn (s)</translation>
    </message>
    <message>
        <source>commanded</source>
        <translation>Sollwert</translation>
    </message>
    <message>
        <source>predicted output</source>
        <translation>vorhergesagte Ausgabe</translation>
    </message>
    <message>
        <source> end</source>
        <translation> Ende</translation>
    </message>
</context>
<context>
    <name>semhap::PlotPanel</name>
    <message>
        <source>Pause</source>
        <translation>Anhalten</translation>
    </message>
    <message>
        <source>Freeze the view; data keep being recorded</source>
        <translation>Ansicht einfrieren; Daten werden weiter aufgezeichnet</translation>
    </message>
    <message>
        <source>Live</source>
        <translation>Live</translation>
    </message>
    <message>
        <source>Follow the newest data again</source>
        <translation>Wieder den neuesten Daten folgen</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Width of the live time window</source>
        <translation>Breite des Live-Zeitfensters</translation>
    </message>
    <message>
        <source>&amp;Window:</source>
        <translation>&amp;Zeitfenster:</translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation>CSV exportieren…</translation>
    </message>
    <message>
        <source>Save the visible time range as CSV</source>
        <translation>Den sichtbaren Zeitbereich als CSV speichern</translation>
    </message>
    <message>
        <source>Export PNG…</source>
        <translation>PNG exportieren…</translation>
    </message>
    <message>
        <source>Save the plots as an image</source>
        <translation>Die Diagramme als Bild speichern</translation>
    </message>
    <message>
        <source>Click to place the cursor; when paused, drag to pan (Shift+drag moves the cursor) and use the wheel to zoom</source>
        <translation>Klicken setzt den Cursor; im angehaltenen Zustand verschiebt Ziehen die Ansicht (Umschalt+Ziehen bewegt den Cursor) und das Mausrad zoomt</translation>
    </message>
    <message>
        <source>pipeline time (s)</source>
        <translation>Pipeline-Zeit (s)</translation>
    </message>
    <message>
        <source>right gripper</source>
        <translation>rechter Greifer</translation>
    </message>
    <message>
        <source>left gripper</source>
        <translation>linker Greifer</translation>
    </message>
    <message>
        <source>%1: force</source>
        <translation>%1: Kraft</translation>
    </message>
    <message>
        <source>F (N)</source>
        <translation>F (N)</translation>
    </message>
    <message>
        <source>F (sum)</source>
        <translation>F (Summe)</translation>
    </message>
    <message>
        <source>%1 %2 N</source>
        <translation>%1 %2 N</translation>
    </message>
    <message>
        <source>%1: contacts</source>
        <translation>%1: Kontakte</translation>
    </message>
    <message>
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <source>N (contacts)</source>
        <translation>N (Kontakte)</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>output</source>
        <translation>Ausgabe</translation>
    </message>
    <message>
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message>
        <source>%1: F %2 N (left %3, right %4), N %5</source>
        <translation>%1: F %2 N (links %3, rechts %4), N %5</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Cannot write %1</source>
        <translation>%1 kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>Export Plots as CSV</source>
        <translation>Diagramme als CSV exportieren</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation>CSV exportieren</translation>
    </message>
    <message>
        <source>Export Plots as PNG</source>
        <translation>Diagramme als PNG exportieren</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG-Bilder (*.png)</translation>
    </message>
    <message>
        <source>Export PNG</source>
        <translation>PNG exportieren</translation>
    </message>
    <message>
        <source>left.f (finger)</source>
        <translation>left.f (Finger)</translation>
    </message>
    <message>
        <source>right.f (finger)</source>
        <translation>right.f (Finger)</translation>
    </message>
    <message>
        <source>%1 %2 (end %3)</source>
        <translation>%1 %2 (Ende %3)</translation>
    </message>
    <message>
        <source>%1: %2 %3</source>
        <translation>%1: %2 %3</translation>
    </message>
    <message>
        <source>Plots</source>
        <translation>Diagramme</translation>
    </message>
</context>
<context>
    <name>semhap::PoseInput</name>
    <message>
        <source>%1 bytes, larger than the limit of %2</source>
        <translation>%1 Bytes, mehr als die Grenze von %2</translation>
    </message>
    <message>
        <source>not JSON: %1 at byte %2</source>
        <translation>kein JSON: %1 bei Byte %2</translation>
    </message>
    <message>
        <source>expected a JSON object</source>
        <translation>JSON-Objekt erwartet</translation>
    </message>
    <message>
        <source>key &apos;hand&apos;: expected &quot;left&quot; or &quot;right&quot;</source>
        <translation>Schlüssel &apos;hand&apos;: &quot;left&quot; oder &quot;right&quot; erwartet</translation>
    </message>
    <message>
        <source>key &apos;pos&apos;: expected an array of 3 numbers (metres)</source>
        <translation>Schlüssel &apos;pos&apos;: Array aus 3 Zahlen erwartet (Meter)</translation>
    </message>
    <message>
        <source>key &apos;pos&apos;: %1 is beyond %2 m from the origin (positions are in metres)</source>
        <translation>Schlüssel &apos;pos&apos;: %1 liegt mehr als %2 m vom Ursprung entfernt (Positionen sind in Metern)</translation>
    </message>
    <message>
        <source>key &apos;quat&apos;: expected an array of 4 numbers [w, x, y, z], not all 0</source>
        <translation>Schlüssel &apos;quat&apos;: Array aus 4 Zahlen [w, x, y, z] erwartet, nicht alle 0</translation>
    </message>
    <message>
        <source>key &apos;yaw&apos;: expected a number (radians)</source>
        <translation>Schlüssel &apos;yaw&apos;: Zahl erwartet (Radiant)</translation>
    </message>
    <message>
        <source>key &apos;grip&apos;: expected a number (newtons)</source>
        <translation>Schlüssel &apos;grip&apos;: Zahl erwartet (Newton)</translation>
    </message>
    <message>
        <source>unknown key &apos;%1&apos; (expected hand, pos, quat or yaw, grip)</source>
        <translation>unbekannter Schlüssel &apos;%1&apos; (erwartet: hand, pos, quat oder yaw, grip)</translation>
    </message>
    <message>
        <source>key &apos;hand&apos; is missing</source>
        <translation>Schlüssel &apos;hand&apos; fehlt</translation>
    </message>
    <message>
        <source>keys &apos;quat&apos; and &apos;yaw&apos;: give one of them</source>
        <translation>Schlüssel &apos;quat&apos; und &apos;yaw&apos;: nur einen von beiden angeben</translation>
    </message>
    <message>
        <source>key &apos;hand&apos;: this scene has no %1 gripper</source>
        <translation>Schlüssel &apos;hand&apos;: Diese Szene hat keinen Greifer &apos;%1&apos;</translation>
    </message>
    <message>
        <source>key &apos;pos&apos; is needed before the %1 hand can be turned on its own</source>
        <translation>Schlüssel &apos;pos&apos; wird benötigt, bevor die Hand &apos;%1&apos; allein gedreht werden kann</translation>
    </message>
    <message>
        <source>datagram %1: %2</source>
        <translation>Datagramm %1: %2</translation>
    </message>
</context>
<context>
    <name>semhap::PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source>System language</source>
        <translation>Systemsprache</translation>
    </message>
    <message>
        <source>Interface language:</source>
        <translation>Sprache der Oberfläche:</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Durchsuchen…</translation>
    </message>
    <message>
        <source>Where recordings go</source>
        <translation>Wohin Aufzeichnungen gehen</translation>
    </message>
    <message>
        <source>Sessions folder:</source>
        <translation>Sitzungsordner:</translation>
    </message>
    <message>
        <source>General</source>
        <translation>Allgemein</translation>
    </message>
    <message>
        <source>Driving</source>
        <translation>Steuern</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(keine)</translation>
    </message>
    <message>
        <source>Left stick →</source>
        <translation>Linker Stick →</translation>
    </message>
    <message>
        <source>Left stick ←</source>
        <translation>Linker Stick ←</translation>
    </message>
    <message>
        <source>Left stick ↓</source>
        <translation>Linker Stick ↓</translation>
    </message>
    <message>
        <source>Left stick ↑</source>
        <translation>Linker Stick ↑</translation>
    </message>
    <message>
        <source>Right stick →</source>
        <translation>Rechter Stick →</translation>
    </message>
    <message>
        <source>Right stick ←</source>
        <translation>Rechter Stick ←</translation>
    </message>
    <message>
        <source>Right stick ↓</source>
        <translation>Rechter Stick ↓</translation>
    </message>
    <message>
        <source>Right stick ↑</source>
        <translation>Rechter Stick ↑</translation>
    </message>
    <message>
        <source>Left trigger</source>
        <translation>Linker Trigger</translation>
    </message>
    <message>
        <source>Left trigger, reversed</source>
        <translation>Linker Trigger, umgekehrt</translation>
    </message>
    <message>
        <source>Right trigger</source>
        <translation>Rechter Trigger</translation>
    </message>
    <message>
        <source>Right trigger, reversed</source>
        <translation>Rechter Trigger, umgekehrt</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Zurück</translation>
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
        <source>Left shoulder</source>
        <translation>Linke Schultertaste</translation>
    </message>
    <message>
        <source>Right shoulder</source>
        <translation>Rechte Schultertaste</translation>
    </message>
    <message>
        <source>D-pad ↑</source>
        <translation>Steuerkreuz ↑</translation>
    </message>
    <message>
        <source>D-pad ↓</source>
        <translation>Steuerkreuz ↓</translation>
    </message>
    <message>
        <source>D-pad ←</source>
        <translation>Steuerkreuz ←</translation>
    </message>
    <message>
        <source>D-pad →</source>
        <translation>Steuerkreuz →</translation>
    </message>
    <message>
        <source> cm/s</source>
        <translation> cm/s</translation>
    </message>
    <message>
        <source>How fast the wrist moves with a key held or a stick pushed all the way; Shift moves at a quarter of it</source>
        <translation>Wie schnell sich das Handgelenk bewegt, solange eine Taste gehalten oder ein Stick ganz ausgelenkt wird; mit Umschalt ein Viertel davon</translation>
    </message>
    <message>
        <source>Drive with a gamepad</source>
        <translation>Mit einem Gamepad steuern</translation>
    </message>
    <message>
        <source>How far a stick may rest off-centre without moving the wrist</source>
        <translation>Wie weit ein Stick außerhalb der Mitte ruhen darf, ohne das Handgelenk zu bewegen</translation>
    </message>
    <message>
        <source>Away / toward:</source>
        <translation>Weg / heran:</translation>
    </message>
    <message>
        <source>Right / left:</source>
        <translation>Rechts / links:</translation>
    </message>
    <message>
        <source>Up / down:</source>
        <translation>Hoch / runter:</translation>
    </message>
    <message>
        <source>Turn:</source>
        <translation>Drehen:</translation>
    </message>
    <message>
        <source>Tilt:</source>
        <translation>Neigen:</translation>
    </message>
    <message>
        <source>Roll:</source>
        <translation>Rollen:</translation>
    </message>
    <message>
        <source>Grip:</source>
        <translation>Griff:</translation>
    </message>
    <message>
        <source>Close / open:</source>
        <translation>Schließen / öffnen:</translation>
    </message>
    <message>
        <source>Switch hand:</source>
        <translation>Hand wechseln:</translation>
    </message>
    <message>
        <source>Grip force +5 N:</source>
        <translation>Griffkraft +5 N:</translation>
    </message>
    <message>
        <source>Grip force −5 N:</source>
        <translation>Griffkraft −5 N:</translation>
    </message>
    <message>
        <source>Hand back (Drive off):</source>
        <translation>Zurückgeben (Steuern aus):</translation>
    </message>
    <message>
        <source>Next camera view:</source>
        <translation>Nächste Kameraansicht:</translation>
    </message>
    <message>
        <source>Stick dead zone:</source>
        <translation>Totzone der Sticks:</translation>
    </message>
    <message>
        <source>Default mapping</source>
        <translation>Standardbelegung</translation>
    </message>
    <message>
        <source>Gamepad</source>
        <translation>Gamepad</translation>
    </message>
    <message>
        <source>Drive with a 3D mouse (through spacenavd)</source>
        <translation>Mit einer 3D-Maus steuern (über spacenavd)</translation>
    </message>
    <message>
        <source>3D mouse</source>
        <translation>3D-Maus</translation>
    </message>
    <message>
        <source>Dead zone:</source>
        <translation>Totzone:</translation>
    </message>
    <message>
        <source>Wrist speed:</source>
        <translation>Handgelenk-Geschwindigkeit:</translation>
    </message>
    <message>
        <source>Publish to Foxglove on port</source>
        <translation>Für Foxglove veröffentlichen auf Port</translation>
    </message>
    <message>
        <source>Viewers:</source>
        <translation>Betrachter:</translation>
    </message>
    <message>
        <source>A new language rebuilds the window where it is, with its layout; the run, a recording, the devices and your edits go on. Recordings go to the sessions folder from the next one on. Foxglove on this computer watches the run live at ws://localhost:PORT (Open connection → Foxglove WebSocket).</source>
        <translation>Eine neue Sprache baut das Fenster dort neu auf, wo es ist, mit seiner Anordnung; der Lauf, eine Aufzeichnung, die Geräte und Ihre Änderungen gehen weiter. Aufzeichnungen gehen ab der nächsten in den Sitzungsordner. Foxglove auf diesem Rechner verfolgt den Lauf live unter ws://localhost:PORT (Open connection → Foxglove WebSocket).</translation>
    </message>
</context>
<context>
    <name>semhap::QuestionnaireWindow</name>
    <message>
        <source>Questionnaire</source>
        <translation>Fragebogen</translation>
    </message>
    <message>
        <source>At the end of the study</source>
        <translation>Zum Abschluss der Studie</translation>
    </message>
    <message>
        <source>After: %1</source>
        <translation>Nach: %1</translation>
    </message>
    <message>
        <source>Thank you!

Please tell the experimenter that you are done.</source>
        <translation>Vielen Dank!

Bitte sagen Sie der Versuchsleitung, dass Sie fertig sind.</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Zurück</translation>
    </message>
    <message>
        <source>Question %1 of %2</source>
        <translation>Frage %1 von %2</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <source>Finish</source>
        <translation>Abschließen</translation>
    </message>
    <message>
        <source>Next</source>
        <translation>Weiter</translation>
    </message>
    <message>
        <source>Enter: close</source>
        <translation>Enter: schließen</translation>
    </message>
    <message>
        <source>Your answer could not be stored: %1</source>
        <translation>Ihre Antwort konnte nicht gespeichert werden: %1</translation>
    </message>
    <message>
        <source>Please set each of the six scales.</source>
        <translation>Bitte stellen Sie jede der sechs Skalen ein.</translation>
    </message>
    <message>
        <source>Please choose one of the points.</source>
        <translation>Bitte wählen Sie einen der Punkte.</translation>
    </message>
    <message>
        <source>Tab: next scale · ← →: set it · Enter: next page · Backspace: back</source>
        <translation>Tab: nächste Skala · ← →: einstellen · Enter: nächste Seite · Rücktaste: zurück</translation>
    </message>
    <message>
        <source>1–%1: choose · ← →: move · Enter: next page · Backspace: back</source>
        <translation>1–%1: wählen · ← →: verschieben · Enter: nächste Seite · Rücktaste: zurück</translation>
    </message>
    <message>
        <source>↑ ↓: choose · Ctrl+↑ ↓: move it · Enter: next page · Backspace: back</source>
        <translation>↑ ↓: wählen · Strg+↑ ↓: verschieben · Enter: nächste Seite · Rücktaste: zurück</translation>
    </message>
    <message>
        <source>Ctrl+Enter: next page · Alt+←: back</source>
        <translation>Strg+Enter: nächste Seite · Alt+←: zurück</translation>
    </message>
</context>
<context>
    <name>semhap::RankingPage</name>
    <message>
        <source>Put the conditions in order: the one you liked most at the top, the one you liked least at the bottom.</source>
        <translation>Bringen Sie die Bedingungen in eine Reihenfolge: die, die Ihnen am besten gefallen hat, nach oben, die, die Ihnen am wenigsten gefallen hat, nach unten.</translation>
    </message>
    <message>
        <source>Move up</source>
        <translation>Nach oben</translation>
    </message>
    <message>
        <source>Move down</source>
        <translation>Nach unten</translation>
    </message>
</context>
<context>
    <name>semhap::ReplayBar</name>
    <message>
        <source>Play or pause the replay</source>
        <translation>Wiedergabe abspielen oder anhalten</translation>
    </message>
    <message>
        <source>Session time: click or drag to scrub</source>
        <translation>Sitzungszeit: klicken oder ziehen zum Durchsuchen</translation>
    </message>
    <message>
        <source>Session seconds per real second</source>
        <translation>Sitzungssekunden pro echter Sekunde</translation>
    </message>
    <message>
        <source>%1×</source>
        <translation>%1×</translation>
    </message>
    <message>
        <source>Run the recorded contact frames through the router in the router editor</source>
        <translation>Die aufgezeichneten Kontakt-Frames durch den Router im Router-Editor leiten</translation>
    </message>
    <message>
        <source>Recorded router</source>
        <translation>Aufgezeichneter Router</translation>
    </message>
    <message>
        <source>Show the events and device frames the session recorded</source>
        <translation>Die aufgezeichneten Ereignisse und Geräte-Frames der Sitzung zeigen</translation>
    </message>
    <message>
        <source>Close replay</source>
        <translation>Wiedergabe schließen</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Anhalten</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Abspielen</translation>
    </message>
    <message>
        <source>%1 / %2 s</source>
        <translation>%1 / %2 s</translation>
    </message>
    <message>
        <source>Showing: re-routed through %1</source>
        <translation>Angezeigt: neu geroutet über %1</translation>
    </message>
    <message>
        <source>Showing: recorded with %1</source>
        <translation>Angezeigt: aufgezeichnet mit %1</translation>
    </message>
    <message>
        <source>unknown date</source>
        <translation>unbekanntes Datum</translation>
    </message>
    <message>
        <source>live rig</source>
        <translation>Live-Rig</translation>
    </message>
    <message>
        <source>Notes: %1</source>
        <translation>Notizen: %1</translation>
    </message>
    <message>
        <source>Recorded by: %1</source>
        <translation>Aufgezeichnet von: %1</translation>
    </message>
    <message>
        <source>Operator: %1, seed %2</source>
        <translation>Bediener: %1, Seed %2</translation>
    </message>
    <message>
        <source>Router: %1</source>
        <translation>Router: %1</translation>
    </message>
    <message>
        <source>Started: %1</source>
        <translation>Begonnen: %1</translation>
    </message>
    <message>
        <source>Ended: %1</source>
        <translation>Beendet: %1</translation>
    </message>
    <message>
        <source>Ended: never closed (the recording was cut off)</source>
        <translation>Beendet: nie geschlossen (die Aufzeichnung brach ab)</translation>
    </message>
    <message>
        <source>Router: %1, edited (it routes differently from %1)</source>
        <translation>Router: %1, bearbeitet (leitet anders als %1)</translation>
    </message>
    <message>
        <source>Re-route</source>
        <translation>Neu leiten</translation>
    </message>
</context>
<context>
    <name>semhap::RouterEditor</name>
    <message>
        <source>Auto-apply</source>
        <translation>Automatisch anwenden</translation>
    </message>
    <message>
        <source>Send every edit that compiles to the running session</source>
        <translation>Jede Änderung, die sich kompilieren lässt, an die laufende Sitzung senden</translation>
    </message>
    <message>
        <source>Not connected: %1</source>
        <translation>Nicht verbunden: %1</translation>
    </message>
    <message>
        <source>Router</source>
        <translation>Router</translation>
    </message>
    <message>
        <source>New (empty)</source>
        <translation>Neu (leer)</translation>
    </message>
    <message>
        <source>New from preset</source>
        <translation>Neu aus Vorlage</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>Öffnen…</translation>
    </message>
    <message>
        <source>Open router</source>
        <translation>Router öffnen</translation>
    </message>
    <message>
        <source>semhap routers (*.json)</source>
        <translation>semhap-Router (*.json)</translation>
    </message>
    <message>
        <source>Save…</source>
        <translation>Speichern…</translation>
    </message>
    <message>
        <source>Save self-contained…</source>
        <translation>Eigenständig speichern…</translation>
    </message>
    <message>
        <source>Arrange</source>
        <translation>Anordnen</translation>
    </message>
    <message>
        <source>Lay the nodes out in columns: detectors, logic, patterns, devices</source>
        <translation>Die Knoten in Spalten anordnen: Detektoren, Logik, Muster, Geräte</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Einpassen</translation>
    </message>
    <message>
        <source>Show the whole graph</source>
        <translation>Den ganzen Graphen zeigen</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <source>Copy</source>
        <translation>Kopieren</translation>
    </message>
    <message>
        <source>Paste</source>
        <translation>Einfügen</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Anwenden</translation>
    </message>
    <message>
        <source>Make this graph the running router</source>
        <translation>Diesen Graphen zum laufenden Router machen</translation>
    </message>
    <message>
        <source>Connected %1 to %2</source>
        <translation>%1 mit %2 verbunden</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a valid id (non-empty, no &apos;:&apos; or spaces)</source>
        <translation>&apos;%1&apos; ist keine gültige ID (nicht leer, ohne &apos;:&apos; und Leerzeichen)</translation>
    </message>
    <message>
        <source>there is already a node &apos;%1&apos;</source>
        <translation>es gibt bereits einen Knoten &apos;%1&apos;</translation>
    </message>
    <message numerus="yes">
        <source>Copied %n node(s)</source>
        <translation>
            <numerusform>%n Knoten kopiert</numerusform>
            <numerusform>%n Knoten kopiert</numerusform>
        </translation>
    </message>
    <message>
        <source>clipboard</source>
        <translation>Zwischenablage</translation>
    </message>
    <message>
        <source>Nothing to paste: %1</source>
        <translation>Nichts einzufügen: %1</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>%1 geöffnet</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>Save self-contained router</source>
        <translation>Eigenständigen Router speichern</translation>
    </message>
    <message>
        <source>Save router</source>
        <translation>Router speichern</translation>
    </message>
    <message>
        <source>untitled</source>
        <translation>unbenannt</translation>
    </message>
    <message>
        <source>Not applied: %1</source>
        <translation>Nicht angewendet: %1</translation>
    </message>
    <message>
        <source>Applied: the running session uses this router now.</source>
        <translation>Angewendet: Die laufende Sitzung verwendet jetzt diesen Router.</translation>
    </message>
    <message>
        <source>Rename pattern</source>
        <translation>Muster umbenennen</translation>
    </message>
    <message>
        <source>Applied: the replay was re-routed through this router.</source>
        <translation>Angewendet: Die Wiedergabe wurde über diesen Router neu geroutet.</translation>
    </message>
    <message>
        <source>Applied: the run waiting behind the replay uses this router.</source>
        <translation>Angewendet: Der Lauf, der hinter der Wiedergabe wartet, verwendet diesen Router.</translation>
    </message>
    <message>
        <source>New router.</source>
        <translation>Neuer Router.</translation>
    </message>
    <message>
        <source>New router from the preset %1.</source>
        <translation>Neuer Router aus der Vorlage %1.</translation>
    </message>
    <message>
        <source>%1 — not saved to a file</source>
        <translation>%1 — nicht in einer Datei gespeichert</translation>
    </message>
    <message>
        <source>%1 — changed since it was saved</source>
        <translation>%1 — seit dem Speichern geändert</translation>
    </message>
    <message>
        <source>Save or Save as… writes it to a file</source>
        <translation>Speichern oder Speichern unter… schreibt ihn in eine Datei</translation>
    </message>
    <message>
        <source>%1 — changed from the preset, not saved to a file</source>
        <translation>%1 — gegenüber der Vorlage geändert, nicht in einer Datei gespeichert</translation>
    </message>
    <message>
        <source>%1 — preset</source>
        <translation>%1 — Vorlage</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <source>Distinctiveness</source>
        <translation>Unterscheidbarkeit</translation>
    </message>
    <message>
        <source>How far apart the messages on each band feel, in just-noticeable differences</source>
        <translation>Wie weit die Nachrichten auf jedem Band spürbar auseinanderliegen, in eben merklichen Unterschieden (JND)</translation>
    </message>
</context>
<context>
    <name>semhap::RouterInspector</name>
    <message>
        <source>Select a node to edit its parameters.</source>
        <translation>Einen Knoten auswählen, um seine Parameter zu bearbeiten.</translation>
    </message>
    <message numerus="yes">
        <source>%n nodes selected.</source>
        <translation>
            <numerusform>%n Knoten ausgewählt.</numerusform>
            <numerusform>%n Knoten ausgewählt.</numerusform>
        </translation>
    </message>
    <message>
        <source>The name events and devices carry</source>
        <translation>Der Name, den Ereignisse und Geräte tragen</translation>
    </message>
    <message>
        <source>id</source>
        <translation>id</translation>
    </message>
    <message>
        <source>%1 (your file)</source>
        <translation>%1 (Ihre Datei)</translation>
    </message>
</context>
<context>
    <name>semhap::RouterPalette</name>
    <message>
        <source>Drag a node type onto the canvas, or double-click it</source>
        <translation>Einen Knotentyp auf die Zeichenfläche ziehen oder doppelklicken</translation>
    </message>
</context>
<context>
    <name>semhap::RouterScene</name>
    <message>
        <source>an output connects to an input, not to another output</source>
        <translation>ein Ausgang wird mit einem Eingang verbunden, nicht mit einem anderen Ausgang</translation>
    </message>
    <message>
        <source>an input connects to an output, not to another input</source>
        <translation>ein Eingang wird mit einem Ausgang verbunden, nicht mit einem anderen Eingang</translation>
    </message>
    <message>
        <source>output %1</source>
        <translation>Ausgabe %1</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
</context>
<context>
    <name>semhap::RunReadouts</name>
    <message>
        <source>Recording to %1 (%2 dropped)</source>
        <translation>Aufnahme nach %1 (%2 verworfen)</translation>
    </message>
    <message>
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message numerus="yes">
        <source>Foxglove: %n viewer(s)</source>
        <translation>
            <numerusform>Foxglove: %n Betrachter</numerusform>
            <numerusform>Foxglove: %n Betrachter</numerusform>
        </translation>
    </message>
    <message>
        <source>Published at %1: %2 message(s) sent, %3 dropped for slow viewers</source>
        <translation>Veröffentlicht unter %1: %2 Nachricht(en) gesendet, %3 für langsame Betrachter verworfen</translation>
    </message>
    <message>
        <source>Replay: nobody drives</source>
        <translation>Wiedergabe: niemand steuert</translation>
    </message>
    <message>
        <source>replay</source>
        <translation>Wiedergabe</translation>
    </message>
    <message>
        <source>%1× real time</source>
        <translation>%1× Echtzeit</translation>
    </message>
    <message>
        <source>paused</source>
        <translation>angehalten</translation>
    </message>
    <message>
        <source>You are driving</source>
        <translation>Sie steuern</translation>
    </message>
    <message>
        <source>Operator: %1</source>
        <translation>Bediener: %1</translation>
    </message>
    <message>
        <source>Live rig on %1</source>
        <translation>Live-Rig auf %1</translation>
    </message>
    <message>
        <source>%1 frames/s, jitter %2 ms</source>
        <translation>%1 Frames/s, Jitter %2 ms</translation>
    </message>
    <message numerus="yes">
        <source>paused: %n frame(s) held</source>
        <translation>
            <numerusform>pausiert: %n Frame zurückgehalten</numerusform>
            <numerusform>pausiert: %n Frames zurückgehalten</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source> · %n malformed</source>
        <translation>
            <numerusform> · %n fehlerhaft</numerusform>
            <numerusform> · %n fehlerhaft</numerusform>
        </translation>
    </message>
    <message>
        <source>Malformed datagram: %1</source>
        <translation>Fehlerhaftes Datagramm: %1</translation>
    </message>
    <message>
        <source>Latest malformed datagram: %1</source>
        <translation>Letztes fehlerhaftes Datagramm: %1</translation>
    </message>
    <message>
        <source>Devices: %1 virtual, %2 connected</source>
        <translation>Geräte: %1 virtuell, %2 verbunden</translation>
    </message>
    <message>
        <source>, %1 connecting</source>
        <translation>, %1 verbindet</translation>
    </message>
    <message>
        <source>, %1 disconnected</source>
        <translation>, %1 getrennt</translation>
    </message>
</context>
<context>
    <name>semhap::RunToolBar</name>
    <message>
        <source>Simulation</source>
        <translation>Simulation</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Starten</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Anhalten</translation>
    </message>
    <message>
        <source>Simulated seconds per real second (Ctrl+- / Ctrl++)</source>
        <translation>Simulierte Sekunden pro echter Sekunde (Strg+- / Strg++)</translation>
    </message>
    <message>
        <source>Real time</source>
        <translation>Echtzeit</translation>
    </message>
    <message>
        <source>%1× speed</source>
        <translation>%1× Tempo</translation>
    </message>
    <message>
        <source>Scene:</source>
        <translation>Szene:</translation>
    </message>
    <message>
        <source>The task to simulate, or a live rig&apos;s frames</source>
        <translation>Die zu simulierende Aufgabe oder die Frames eines Live-Rigs</translation>
    </message>
    <message>
        <source>Live rig…</source>
        <translation>Live-Rig…</translation>
    </message>
    <message>
        <source>Router:</source>
        <translation>Router:</translation>
    </message>
    <message>
        <source>Session name</source>
        <translation>Sitzungsname</translation>
    </message>
    <message>
        <source>Names the next recording&apos;s file (empty: scene, router and time); File → Preferences says where it goes</source>
        <translation>Benennt die Datei der nächsten Aufzeichnung (leer: Szene, Router und Zeit); Datei → Einstellungen legt fest, wohin sie geht</translation>
    </message>
    <message>
        <source>Session notes</source>
        <translation>Notizen</translation>
    </message>
    <message>
        <source>Kept with the next recording (participant, condition, …)</source>
        <translation>Wird mit der nächsten Aufnahme gespeichert (Versuchsperson, Bedingung, …)</translation>
    </message>
    <message>
        <source>Gripper</source>
        <translation>Greifer</translation>
    </message>
    <message>
        <source>Scene&apos;s own</source>
        <translation>Eigene der Szene</translation>
    </message>
    <message>
        <source>Other file…</source>
        <translation>Andere Datei…</translation>
    </message>
    <message>
        <source>Open gripper adapter</source>
        <translation>Greifer-Adapter öffnen</translation>
    </message>
    <message>
        <source>Gripper adapters (*.json)</source>
        <translation>Greifer-Adapter (*.json)</translation>
    </message>
    <message>
        <source>Gripper: %1
The scene&apos;s own grippers, or a gripper adapter&apos;s model in their place</source>
        <translation>Greifer: %1
Die eigenen Greifer der Szene oder an ihrer Stelle das Modell eines Greifer-Adapters</translation>
    </message>
    <message>
        <source>the scene&apos;s own</source>
        <translation>die eigenen der Szene</translation>
    </message>
    <message>
        <source>Which feedback design turns events into patterns</source>
        <translation>Das Rückmeldungsdesign, das Ereignisse in Muster umsetzt</translation>
    </message>
</context>
<context>
    <name>semhap::SessionExport</name>
    <message>
        <source>XDF for LSL labs, session time with clock offsets (*.xdf)</source>
        <translation>XDF für LSL-Labore, Sitzungszeit mit Uhrenversatz (*.xdf)</translation>
    </message>
    <message>
        <source>XDF for LSL labs, on LSL&apos;s clock (*.xdf)</source>
        <translation>XDF für LSL-Labore, auf der LSL-Uhr (*.xdf)</translation>
    </message>
    <message>
        <source>MCAP for Foxglove, PlotJuggler and Rerun (*.mcap)</source>
        <translation>MCAP für Foxglove, PlotJuggler und Rerun (*.mcap)</translation>
    </message>
    <message>
        <source>Export session</source>
        <translation>Sitzung exportieren</translation>
    </message>
</context>
<context>
    <name>semhap::SessionReplay</name>
    <message>
        <source>Replay: a live rig&apos;s session has no scene</source>
        <translation>Wiedergabe: Die Sitzung eines Live-Rigs hat keine Szene</translation>
    </message>
    <message>
        <source>Replay: no scene state recorded</source>
        <translation>Wiedergabe: kein Szenenzustand aufgezeichnet</translation>
    </message>
    <message>
        <source>its scene states do not fit scene %1</source>
        <translation>seine Szenenzustände passen nicht zur Szene %1</translation>
    </message>
    <message>
        <source>Replay: the scene cannot be shown (%1)</source>
        <translation>Wiedergabe: Die Szene kann nicht gezeigt werden (%1)</translation>
    </message>
    <message>
        <source>Replay: a robot&apos;s recording has no scene</source>
        <translation>Wiedergabe: Eine Roboteraufzeichnung hat keine Szene</translation>
    </message>
    <message>
        <source>Replay</source>
        <translation>Wiedergabe</translation>
    </message>
</context>
<context>
    <name>semhap::SimViewport</name>
    <message>
        <source>Reset camera</source>
        <translation>Kamera zurücksetzen</translation>
    </message>
    <message>
        <source>Waiting for the simulation…</source>
        <translation>Warten auf die Simulation…</translation>
    </message>
    <message>
        <source>No scene loaded</source>
        <translation>Keine Szene geladen</translation>
    </message>
    <message>
        <source>You are driving (right hand)</source>
        <translation>Sie steuern (rechte Hand)</translation>
    </message>
    <message>
        <source>You are driving (left hand)</source>
        <translation>Sie steuern (linke Hand)</translation>
    </message>
    <message>
        <source>Grip: closed, %1 N</source>
        <translation>Griff: geschlossen, %1 N</translation>
    </message>
    <message>
        <source>Grip: open (closes to %1 N)</source>
        <translation>Griff: offen (schließt mit %1 N)</translation>
    </message>
    <message>
        <source>W A S D move · R F up/down · Q E turn · Space grip · +/- force</source>
        <translation>W A S D bewegen · R F hoch/runter · Q E drehen · Leertaste greifen · +/- Kraft</translation>
    </message>
    <message>
        <source>Tab: switch hand</source>
        <translation>Tab: Hand wechseln</translation>
    </message>
    <message>
        <source>Simulated operator</source>
        <translation>Simulierter Bediener</translation>
    </message>
    <message>
        <source>Click here and press W A S D to drive</source>
        <translation>Hier klicken und W A S D drücken, um zu steuern</translation>
    </message>
    <message>
        <source>Across the jaws</source>
        <translation>Quer zu den Backen</translation>
    </message>
    <message>
        <source>From the top</source>
        <translation>Von oben</translation>
    </message>
    <message>
        <source>From the side</source>
        <translation>Von der Seite</translation>
    </message>
    <message>
        <source>Follow the hand</source>
        <translation>Der Hand folgen</translation>
    </message>
    <message>
        <source>Resting on what is below: the wrist stops here</source>
        <translation>Liegt auf dem Untergrund auf: das Handgelenk hält hier an</translation>
    </message>
    <message>
        <source>Wrist %1 cm above the surface below</source>
        <translation>Handgelenk %1 cm über der Fläche darunter</translation>
    </message>
    <message>
        <source>W goes %1, D goes %2 · 1–4 camera</source>
        <translation>W geht %1, D geht %2 · 1–4 Kamera</translation>
    </message>
    <message>
        <source>Grip: %1 N asked, applied at the run&apos;s next step</source>
        <translation>Griff: %1 N verlangt, der nächste Schritt des Laufs setzt sie um</translation>
    </message>
    <message>
        <source>Grip: opening, %1 N</source>
        <translation>Griff: öffnet, %1 N</translation>
    </message>
    <message>
        <source>Grip: %1 N of %2 N, tightening on what the pads touch</source>
        <translation>Griff: %1 N von %2 N, fasst fester, was die Backen berühren</translation>
    </message>
    <message>
        <source>Grip: %1 N of %2 N, closing slowly until both pads touch</source>
        <translation>Griff: %1 N von %2 N, schließt langsam, bis beide Backen berühren</translation>
    </message>
    <message>
        <source>Contact forces</source>
        <translation>Kontaktkräfte</translation>
    </message>
    <message>
        <source>Back to the default view (%1; Home in the viewport)</source>
        <translation>Zurück zur Standardansicht (%1; Pos1 in der Szenenansicht)</translation>
    </message>
    <message>
        <source>Show contact forces as arrows in the viewport (%1)</source>
        <translation>Kontaktkräfte als Pfeile in der Szenenansicht zeigen (%1)</translation>
    </message>
</context>
<context>
    <name>semhap::SpaceMouseInput</name>
    <message>
        <source>3D mouse</source>
        <translation>3D-Maus</translation>
    </message>
</context>
<context>
    <name>semhap::Studio</name>
    <message>
        <source>%1: could not write the screenshot</source>
        <translation>%1: Bildschirmfoto konnte nicht geschrieben werden</translation>
    </message>
    <message>
        <source>Some of what you left open could not be opened again</source>
        <translation>Einiges von dem, was Sie offen gelassen hatten, ließ sich nicht wieder öffnen</translation>
    </message>
    <message>
        <source>Your work is not being saved</source>
        <translation>Ihre Arbeit wird nicht gesichert</translation>
    </message>
    <message>
        <source>%1: no participant &apos;%2&apos;</source>
        <translation>%1: keine Versuchsperson &apos;%2&apos;</translation>
    </message>
</context>
<context>
    <name>semhap::StudyDocument</name>
    <message>
        <source>The break is over.</source>
        <translation>Die Pause ist vorbei.</translation>
    </message>
    <message>
        <source>The trial that ran could not be stored as aborted</source>
        <translation>Der laufende Durchgang konnte nicht als abgebrochen gespeichert werden</translation>
    </message>
    <message>
        <source>no study is open</source>
        <translation>keine Studie ist geöffnet</translation>
    </message>
    <message>
        <source>choose a participant first</source>
        <translation>wählen Sie zuerst eine Versuchsperson</translation>
    </message>
    <message>
        <source>a trial runs already</source>
        <translation>es läuft bereits ein Durchgang</translation>
    </message>
    <message>
        <source>the break is on: skip it to go on at once</source>
        <translation>die Pause läuft: überspringen Sie sie, um sofort weiterzumachen</translation>
    </message>
    <message>
        <source>the next step is no practice round or trial</source>
        <translation>der nächste Schritt ist weder Übung noch Durchgang</translation>
    </message>
    <message>
        <source>The end of %1 could not be stored</source>
        <translation>Das Ende von „%1“ konnte nicht gespeichert werden</translation>
    </message>
    <message>
        <source>%1: done.</source>
        <translation>%1: erledigt.</translation>
    </message>
    <message>
        <source>no trial runs</source>
        <translation>es läuft kein Durchgang</translation>
    </message>
    <message>
        <source>%1 was aborted</source>
        <translation>„%1“ wurde abgebrochen</translation>
    </message>
    <message>
        <source>%1 could not be stored as aborted</source>
        <translation>„%1“ konnte nicht als abgebrochen gespeichert werden</translation>
    </message>
    <message numerus="yes">
        <source>until %n transfer(s) or %1 s</source>
        <translation>
            <numerusform>bis %n Würfel transportiert ist oder %1 s</numerusform>
            <numerusform>bis %n Würfel transportiert sind oder %1 s</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>until %n transfer(s)</source>
        <translation>
            <numerusform>bis %n Würfel transportiert ist</numerusform>
            <numerusform>bis %n Würfel transportiert sind</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Practice — %1 (%2)</source>
        <translation>Übung — %1 (%2)</translation>
    </message>
    <message>
        <source>Trial %1 of %2 — %3 (%4 s)</source>
        <translation>Durchgang %1 von %2 — %3 (%4 s)</translation>
    </message>
    <message>
        <source>Questionnaire after %1</source>
        <translation>Fragebogen nach %1</translation>
    </message>
    <message>
        <source>Final questionnaire</source>
        <translation>Abschlussfragebogen</translation>
    </message>
    <message>
        <source>All steps done</source>
        <translation>Alle Schritte erledigt</translation>
    </message>
    <message>
        <source>%1: cannot create the folder</source>
        <translation>%1: Ordner kann nicht angelegt werden</translation>
    </message>
</context>
<context>
    <name>semhap::StudyMenu</name>
    <message>
        <source>Stud&amp;y</source>
        <translation>Stud&amp;ie</translation>
    </message>
    <message>
        <source>New study…</source>
        <translation>Neue Studie…</translation>
    </message>
    <message>
        <source>Open study…</source>
        <translation>Studie öffnen…</translation>
    </message>
    <message>
        <source>Export results…</source>
        <translation>Ergebnisse exportieren…</translation>
    </message>
    <message>
        <source>Close study</source>
        <translation>Studie schließen</translation>
    </message>
    <message>
        <source>Start a study from a protocol: participants, their orders of conditions, timed trials and questionnaires</source>
        <translation>Eine Studie nach einem Protokoll beginnen: Versuchspersonen, ihre Reihenfolgen der Bedingungen, zeitlich begrenzte Durchgänge und Fragebögen</translation>
    </message>
    <message>
        <source>Write the study&apos;s results into a folder: measures.csv (tidy, for R or pandas), trials.csv, answers.csv, and the analysis&apos; report with a box plot per measure</source>
        <translation>Die Ergebnisse der Studie in einen Ordner schreiben: measures.csv (tidy, für R oder pandas), trials.csv, answers.csv und den Bericht der Auswertung mit einem Boxplot je Messgröße</translation>
    </message>
    <message>
        <source>New study: its protocol</source>
        <translation>Neue Studie: ihr Protokoll</translation>
    </message>
    <message>
        <source>semhap study protocols (*.json)</source>
        <translation>semhap-Studienprotokolle (*.json)</translation>
    </message>
    <message>
        <source>New study: where to keep it</source>
        <translation>Neue Studie: wo sie gespeichert wird</translation>
    </message>
    <message>
        <source>semhap studies (*.db)</source>
        <translation>semhap-Studien (*.db)</translation>
    </message>
    <message>
        <source>Could not create the study</source>
        <translation>Die Studie konnte nicht angelegt werden</translation>
    </message>
    <message>
        <source>Open study</source>
        <translation>Studie öffnen</translation>
    </message>
    <message>
        <source>semhap studies (*.db);;All files (*)</source>
        <translation>semhap-Studien (*.db);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Could not open the study %1</source>
        <translation>Die Studie %1 konnte nicht geöffnet werden</translation>
    </message>
    <message>
        <source>Export the study&apos;s results into</source>
        <translation>Ergebnisse der Studie exportieren nach</translation>
    </message>
    <message>
        <source>Could not export the study&apos;s results</source>
        <translation>Die Ergebnisse der Studie ließen sich nicht exportieren</translation>
    </message>
    <message>
        <source>Exported %1 files into %2: measures.csv, trials.csv, answers.csv and %3/report.md</source>
        <translation>%1 Dateien nach %2 exportiert: measures.csv, trials.csv, answers.csv und %3/report.md</translation>
    </message>
    <message>
        <source>%1 runs. Closing the study aborts it: it will not count and is due again when the study is opened again.</source>
        <translation>„%1“ läuft. Wenn Sie die Studie schließen, wird das abgebrochen: Es zählt nicht und ist wieder an der Reihe, wenn die Studie wieder geöffnet wird.</translation>
    </message>
</context>
<context>
    <name>semhap::StudyPanel</name>
    <message>
        <source>running</source>
        <translation>läuft</translation>
    </message>
    <message>
        <source>done</source>
        <translation>erledigt</translation>
    </message>
    <message>
        <source>aborted</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>invalid</source>
        <translation>ungültig</translation>
    </message>
    <message>
        <source>interrupted</source>
        <translation>unterbrochen</translation>
    </message>
    <message>
        <source>Practice</source>
        <translation>Übung</translation>
    </message>
    <message>
        <source>Trial %1</source>
        <translation>Durchgang %1</translation>
    </message>
    <message>
        <source>Questionnaire</source>
        <translation>Fragebogen</translation>
    </message>
    <message>
        <source>Final questionnaire</source>
        <translation>Abschlussfragebogen</translation>
    </message>
    <message>
        <source>No study is open. A study runs a protocol&apos;s conditions, trials and questionnaires with each participant and keeps everything in one file.</source>
        <translation>Keine Studie ist geöffnet. Eine Studie führt jede Versuchsperson durch die Bedingungen, Durchgänge und Fragebögen eines Protokolls und hält alles in einer Datei fest.</translation>
    </message>
    <message>
        <source>e.g. P01</source>
        <translation>z. B. P01</translation>
    </message>
    <message>
        <source>A participant&apos;s ID: 1 to 32 letters, digits, _ . or -. No names needed.</source>
        <translation>Die Kennung einer Versuchsperson: 1 bis 32 Buchstaben, Ziffern, _ . oder -. Namen sind nicht nötig.</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Hinzufügen</translation>
    </message>
    <message>
        <source>Participants</source>
        <translation>Versuchspersonen</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Stand</translation>
    </message>
    <message>
        <source>Skip break</source>
        <translation>Pause überspringen</translation>
    </message>
    <message>
        <source>Abort…</source>
        <translation>Abbrechen…</translation>
    </message>
    <message>
        <source>End the trial now; it does not count and is due again</source>
        <translation>Den Durchgang jetzt beenden; er zählt nicht und ist wieder an der Reihe</translation>
    </message>
    <message>
        <source>Mark invalid…</source>
        <translation>Ungültig…</translation>
    </message>
    <message>
        <source>The done trial chosen in the list does not count: it is due again</source>
        <translation>Der in der Liste gewählte erledigte Durchgang zählt nicht: Er ist wieder an der Reihe</translation>
    </message>
    <message>
        <source>Add a participant, or choose one.</source>
        <translation>Fügen Sie eine Versuchsperson hinzu, oder wählen Sie eine.</translation>
    </message>
    <message>
        <source>Order of %1: %2</source>
        <translation>Reihenfolge für %1: %2</translation>
    </message>
    <message>
        <source>Attempt %1</source>
        <translation>Versuch %1</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>answered</source>
        <translation>beantwortet</translation>
    </message>
    <message>
        <source>next</source>
        <translation>als Nächstes</translation>
    </message>
    <message>
        <source>Now: %1</source>
        <translation>Jetzt: %1</translation>
    </message>
    <message>
        <source>Paused. </source>
        <translation>Angehalten. </translation>
    </message>
    <message>
        <source>Left of the trial</source>
        <translation>Restzeit des Durchgangs</translation>
    </message>
    <message>
        <source>at most %1</source>
        <translation>höchstens %1</translation>
    </message>
    <message>
        <source>%1 of %2 transfers</source>
        <translation>%1 von %2 Würfeln transportiert</translation>
    </message>
    <message>
        <source>Practice so far</source>
        <translation>Übung bisher</translation>
    </message>
    <message>
        <source>Next: %1</source>
        <translation>Als Nächstes: %1</translation>
    </message>
    <message>
        <source>Break before the next trial</source>
        <translation>Pause vor dem nächsten Durchgang</translation>
    </message>
    <message>
        <source>Choose a participant.</source>
        <translation>Wählen Sie eine Versuchsperson.</translation>
    </message>
    <message>
        <source>This participant has done every step.</source>
        <translation>Diese Versuchsperson hat alle Schritte erledigt.</translation>
    </message>
    <message>
        <source>Start when the participant is ready.</source>
        <translation>Starten Sie, sobald die Versuchsperson bereit ist.</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Fortsetzen</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Anhalten</translation>
    </message>
    <message>
        <source>Could not start %1</source>
        <translation>„%1“ konnte nicht gestartet werden</translation>
    </message>
    <message>
        <source>Abort the trial</source>
        <translation>Durchgang abbrechen</translation>
    </message>
    <message>
        <source>Why is %1 aborted? It will not count and is due again.</source>
        <translation>Warum wird „%1“ abgebrochen? Es zählt nicht und ist wieder an der Reihe.</translation>
    </message>
    <message>
        <source>Could not store %1 as aborted</source>
        <translation>„%1“ konnte nicht als abgebrochen gespeichert werden</translation>
    </message>
    <message>
        <source>Mark the trial invalid</source>
        <translation>Durchgang als ungültig markieren</translation>
    </message>
    <message>
        <source>Why does this trial not count? It is kept, marked invalid, and is due again.</source>
        <translation>Warum zählt dieser Durchgang nicht? Er bleibt erhalten, als ungültig markiert, und ist wieder an der Reihe.</translation>
    </message>
    <message>
        <source>Could not mark the trial invalid</source>
        <translation>Der Durchgang konnte nicht als ungültig markiert werden</translation>
    </message>
    <message>
        <source>Questionnaire opens it for the participant, in a window of its own.</source>
        <translation>„Fragebogen“ öffnet ihn für die Versuchsperson in einem eigenen Fenster.</translation>
    </message>
    <message>
        <source>at %1× real time</source>
        <translation>mit %1× Echtzeit</translation>
    </message>
    <message>
        <source>No participant chosen</source>
        <translation>Keine Versuchsperson gewählt</translation>
    </message>
    <message>
        <source>Study</source>
        <translation>Studie</translation>
    </message>
</context>
<context>
    <name>semhap::TlxPage</name>
    <message>
        <source>Mental demand</source>
        <translation>Geistige Anforderung</translation>
    </message>
    <message>
        <source>How mentally demanding was the task?</source>
        <translation>Wie hoch waren die geistigen Anforderungen der Aufgabe?</translation>
    </message>
    <message>
        <source>Very low</source>
        <translation>Sehr gering</translation>
    </message>
    <message>
        <source>Very high</source>
        <translation>Sehr hoch</translation>
    </message>
    <message>
        <source>Physical demand</source>
        <translation>Körperliche Anforderung</translation>
    </message>
    <message>
        <source>How physically demanding was the task?</source>
        <translation>Wie hoch waren die körperlichen Anforderungen der Aufgabe?</translation>
    </message>
    <message>
        <source>Temporal demand</source>
        <translation>Zeitliche Anforderung</translation>
    </message>
    <message>
        <source>How hurried or rushed was the pace of the task?</source>
        <translation>Wie hoch war der Zeitdruck, unter dem Sie die Aufgabe erledigen mussten?</translation>
    </message>
    <message>
        <source>Performance</source>
        <translation>Leistung</translation>
    </message>
    <message>
        <source>How successful were you in accomplishing what you were asked to do?</source>
        <translation>Wie erfolgreich haben Sie Ihrer Meinung nach die vorgegebene Aufgabe erfüllt?</translation>
    </message>
    <message>
        <source>Perfect</source>
        <translation>Perfekt</translation>
    </message>
    <message>
        <source>Failure</source>
        <translation>Misserfolg</translation>
    </message>
    <message>
        <source>Effort</source>
        <translation>Anstrengung</translation>
    </message>
    <message>
        <source>How hard did you have to work to accomplish your level of performance?</source>
        <translation>Wie sehr mussten Sie sich anstrengen, um Ihre Leistung zu erreichen?</translation>
    </message>
    <message>
        <source>Frustration</source>
        <translation>Frustration</translation>
    </message>
    <message>
        <source>How insecure, discouraged, irritated, stressed, and annoyed were you?</source>
        <translation>Wie unsicher, entmutigt, gereizt, gestresst und verärgert waren Sie?</translation>
    </message>
    <message>
        <source>How was the task you just did? Set each of the six scales.</source>
        <translation>Wie war die Aufgabe, die Sie gerade erledigt haben? Stellen Sie jede der sechs Skalen ein.</translation>
    </message>
    <message>
        <source>–</source>
        <comment>a TLX scale not set yet</comment>
        <translation>–</translation>
    </message>
</context>
<context>
    <name>semhap::UserPatterns</name>
    <message>
        <source>A pattern needs a name.</source>
        <translation>Ein Muster braucht einen Namen.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; cannot name a file: a pattern&apos;s name may not contain &apos;/&apos; or &apos;\&apos; or begin with &apos;.&apos;.</source>
        <translation>„%1“ kann keine Datei benennen: Der Name eines Musters darf weder „/“ noch „\“ enthalten noch mit „.“ beginnen.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is the name of a built-in pattern: choose another.</source>
        <translation>„%1“ ist der Name eines eingebauten Musters: Wählen Sie einen anderen.</translation>
    </message>
    <message>
        <source>Another of your patterns is named &apos;%1&apos;: choose another name.</source>
        <translation>Ein anderes Ihrer Muster heißt „%1“: Wählen Sie einen anderen Namen.</translation>
    </message>
</context>
<context>
    <name>semhap::WaveformDesigner</name>
    <message numerus="yes">
        <source>%n point(s)</source>
        <translation>
            <numerusform>%n Punkt</numerusform>
            <numerusform>%n Punkte</numerusform>
        </translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Gestoppt</translation>
    </message>
    <message>
        <source>Playing on %1</source>
        <translation>Spielt auf %1</translation>
    </message>
    <message>
        <source>Releasing on %1</source>
        <translation>Klingt auf %1 ab</translation>
    </message>
    <message>
        <source> — disarmed: arm it in the Devices panel to feel it</source>
        <translation> — gesperrt: unter „Geräte“ freigeben, um es zu spüren</translation>
    </message>
    <message>
        <source>New</source>
        <translation>Neu</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>Öffnen…</translation>
    </message>
    <message>
        <source>Open pattern</source>
        <translation>Muster öffnen</translation>
    </message>
    <message>
        <source>Could not open %1</source>
        <translation>%1 konnte nicht geöffnet werden</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Speichern</translation>
    </message>
    <message>
        <source>Save as…</source>
        <translation>Speichern unter…</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Duplizieren</translation>
    </message>
    <message>
        <source>Make an editable copy of this pattern</source>
        <translation>Eine bearbeitbare Kopie dieses Musters anlegen</translation>
    </message>
    <message>
        <source>Import…</source>
        <translation>Importieren…</translation>
    </message>
    <message>
        <source>Import an Apple AHAP or a Meta .haptic file as a new pattern</source>
        <translation>Eine Apple-AHAP- oder Meta-.haptic-Datei als neues Muster importieren</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>Exportieren…</translation>
    </message>
    <message>
        <source>Export the pattern as AHAP or .haptic (docs/convert.md)</source>
        <translation>Das Muster als AHAP oder .haptic exportieren (docs/convert.md)</translation>
    </message>
    <message>
        <source>Library</source>
        <translation>Bibliothek</translation>
    </message>
    <message>
        <source>Built-in patterns (locked) and your own, from %1</source>
        <translation>Eingebaute Muster (schreibgeschützt) und Ihre eigenen, aus %1</translation>
    </message>
    <message>
        <source>Add track</source>
        <translation>Neue Spur</translation>
    </message>
    <message>
        <source>A new track, driving every channel</source>
        <translation>Eine neue Spur, die jeden Kanal ansteuert</translation>
    </message>
    <message>
        <source>Add part</source>
        <translation>Neuer Abschnitt</translation>
    </message>
    <message>
        <source>Give the selected track an attack, a sustain or a release</source>
        <translation>Der ausgewählten Spur einen Anstieg, ein Halten oder ein Abklingen hinzufügen</translation>
    </message>
    <message>
        <source>Attack</source>
        <translation>Anstieg</translation>
    </message>
    <message>
        <source>Sustain</source>
        <translation>Halten</translation>
    </message>
    <message>
        <source>Release</source>
        <translation>Abklingen</translation>
    </message>
    <message>
        <source>Add input</source>
        <translation>Neuer Eingang</translation>
    </message>
    <message>
        <source>Another input of the selected sum, product or sequence</source>
        <translation>Ein weiterer Eingang für die ausgewählte Summe (sum), das Produkt (product) oder die Folge (sequence)</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Remove the selected node</source>
        <translation>Den ausgewählten Knoten entfernen</translation>
    </message>
    <message>
        <source>JSON</source>
        <translation>JSON</translation>
    </message>
    <message>
        <source>The device model the pattern is for; the preview predicts its output</source>
        <translation>Das Gerätemodell, für das das Muster bestimmt ist; die Vorschau sagt seine Ausgabe voraus</translation>
    </message>
    <message>
        <source>The intensity the pattern begins with (preview and audition)</source>
        <translation>Die Intensität, mit der das Muster beginnt (Vorschau und Vorhören)</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Hold</source>
        <translation>Halten</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>Modell</translation>
    </message>
    <message>
        <source>Intensity</source>
        <translation>Intensität</translation>
    </message>
    <message>
        <source>End at</source>
        <translation>Ende bei</translation>
    </message>
    <message>
        <source>Where the audition plays: a bound device of the run (the run pauses), or a virtual one</source>
        <translation>Wo das Vorhören spielt: ein zugeordnetes Gerät des Laufs (der Lauf hält an) oder ein virtuelles</translation>
    </message>
    <message>
        <source>Audition</source>
        <translation>Vorhören</translation>
    </message>
    <message>
        <source>Begin the pattern on the device now (again: restart it)</source>
        <translation>Das Muster jetzt auf dem Gerät beginnen (erneut: neu starten)</translation>
    </message>
    <message>
        <source>End</source>
        <translation>Beenden</translation>
    </message>
    <message>
        <source>End the pattern: its release plays</source>
        <translation>Das Muster beenden: Sein Abklingen spielt</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>Send the device to zero now (Esc stops everything)</source>
        <translation>Das Gerät sofort auf null setzen (Esc stoppt alles)</translation>
    </message>
    <message>
        <source>Audition on</source>
        <translation>Vorhören auf</translation>
    </message>
    <message>
        <source>Built-in, read-only: duplicate it to edit</source>
        <translation>Eingebaut, schreibgeschützt: zum Bearbeiten duplizieren</translation>
    </message>
    <message>
        <source>virtual (audition only)</source>
        <translation>virtuell (nur Vorhören)</translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation>%1 exportiert</translation>
    </message>
    <message>
        <source>Could not save</source>
        <translation>Speichern fehlgeschlagen</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>Save pattern</source>
        <translation>Muster speichern</translation>
    </message>
    <message>
        <source>Patterns (*.json)</source>
        <translation>Muster (*.json)</translation>
    </message>
    <message>
        <source>Could not save %1</source>
        <translation>%1 konnte nicht gespeichert werden</translation>
    </message>
    <message>
        <source>Import haptic file</source>
        <translation>Haptik-Datei importieren</translation>
    </message>
    <message>
        <source>Could not import %1</source>
        <translation>%1 konnte nicht importiert werden</translation>
    </message>
    <message>
        <source>Export pattern</source>
        <translation>Muster exportieren</translation>
    </message>
    <message>
        <source>Could not export %1</source>
        <translation>%1 konnte nicht exportiert werden</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt; is built in and read-only. &lt;b&gt;Duplicate&lt;/b&gt; it to edit a copy.</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; ist eingebaut und schreibgeschützt. &lt;b&gt;Duplizieren&lt;/b&gt; Sie es, um eine Kopie zu bearbeiten.</translation>
    </message>
    <message>
        <source>%1%2</source>
        <translation>%1%2</translation>
    </message>
    <message>
        <source>New pattern</source>
        <translation>Neues Muster</translation>
    </message>
    <message>
        <source> — not saved</source>
        <translation> — nicht gespeichert</translation>
    </message>
    <message>
        <source>Pattern %1 (%2)</source>
        <translation>Muster %1 (%2)</translation>
    </message>
    <message>
        <source>Track %1: %2</source>
        <translation>Spur %1: %2</translation>
    </message>
    <message>
        <source>in</source>
        <translation>Eingang</translation>
    </message>
    <message>
        <source>Edit JSON</source>
        <translation>JSON bearbeiten</translation>
    </message>
    <message>
        <source>Unknown device model &apos;%1&apos; (built-in: %2)</source>
        <translation>Unbekanntes Gerätemodell &apos;%1&apos; (eingebaut: %2)</translation>
    </message>
    <message>
        <source>Cannot audition</source>
        <translation>Vorhören nicht möglich</translation>
    </message>
    <message>
        <source>unknown device model %1</source>
        <translation>unbekanntes Gerätemodell %1</translation>
    </message>
    <message>
        <source>Cannot audition on %1</source>
        <translation>Vorhören auf %1 nicht möglich</translation>
    </message>
    <message>
        <source>Waveform tree</source>
        <translation>Wellenformbaum</translation>
    </message>
    <message>
        <source>Valid pattern</source>
        <translation>Gültiges Muster</translation>
    </message>
    <message>
        <source>When the preview and the audition end the pattern (its release starts)</source>
        <translation>Wann Vorschau und Vorhören das Muster beenden (sein Abklingen beginnt)</translation>
    </message>
    <message>
        <source>Preview and audition without an end: the sustain goes on</source>
        <translation>Vorschau und Vorhören ohne Ende: das Halten geht weiter</translation>
    </message>
    <message>
        <source>Could not save %1 as %2</source>
        <translation>%1 konnte nicht als %2 gespeichert werden</translation>
    </message>
    <message>
        <source>Saved %1, but could not remove %2</source>
        <translation>%1 gespeichert, aber %2 konnte nicht entfernt werden</translation>
    </message>
    <message>
        <source>Renamed %1 to %2</source>
        <translation>%1 in %2 umbenannt</translation>
    </message>
    <message>
        <source>Pattern</source>
        <translation>Muster</translation>
    </message>
    <message>
        <source>New, open, save as, import and export</source>
        <translation>Neu, öffnen, speichern unter, importieren und exportieren</translation>
    </message>
    <message>
        <source>Not saved yet: %1</source>
        <translation>Noch nicht gespeichert: %1</translation>
    </message>
    <message>
        <source>Patterns</source>
        <translation>Muster</translation>
    </message>
    <message>
        <source>Open a pattern, an AHAP, a .haptic or an HJIF file</source>
        <translation>Ein Muster, eine AHAP-, eine .haptic- oder eine HJIF-Datei öffnen</translation>
    </message>
    <message>
        <source>Patterns and haptic files (*.json *.ahap *.haptic *.hjif)</source>
        <translation>Muster und Haptik-Dateien (*.json *.ahap *.haptic *.hjif)</translation>
    </message>
    <message>
        <source>Haptic files (*.ahap *.haptic *.hjif)</source>
        <translation>Haptik-Dateien (*.ahap *.haptic *.hjif)</translation>
    </message>
    <message>
        <source>Apple AHAP (*.ahap);;Meta Haptics (*.haptic);;MPEG haptics (*.hjif)</source>
        <translation>Apple AHAP (*.ahap);;Meta Haptics (*.haptic);;MPEG-Haptik (*.hjif)</translation>
    </message>
</context>
<context>
    <name>semhap::Workspace</name>
    <message>
        <source>%1: the file as it was is kept as %2</source>
        <translation>%1: die Datei, wie sie war, bleibt als %2 erhalten</translation>
    </message>
    <message>
        <source>%1 stays unbound: the router that runs has no %2 device &apos;%3&apos;</source>
        <translation>%1 bleibt ungebunden: der laufende Router hat kein %2-Gerät &apos;%3&apos;</translation>
    </message>
</context>
</TS>

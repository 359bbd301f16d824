<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_GB" sourcelanguage="en_GB">
<context>
    <name>RouterCommands</name>
    <message>
        <source>Add %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connect %1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set %1.%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rename %1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>StudioOptions</name>
    <message>
        <source>semhap studio: watch and tune semantic haptic feedback on a simulated task.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scene: a bundled name or an MJCF file.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>scene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Router: a preset name or a semhap.router/1 file.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>router</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The operator&apos;s seed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>n</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cubes in play (default: the scene&apos;s).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulated seconds per real second.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>factor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open paused.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Grab the whole window to this PNG, then quit.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>file.png</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Grab (with --screenshot) and quit after this many seconds.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>seconds</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Window size, e.g. 1280x800.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>WxH</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>User interface language: en or de.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>UDP port of the network pose input (0: off).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>port</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ignore the saved window layout.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unexpected argument &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--%1: expected a number from %2 to %3, got &apos;%4&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--size: expected WIDTHxHEIGHT such as 1280x800, got &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--language: expected en or de, got &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start on a live rig: contact frames over UDP on this port (ADDRESS:PORT to listen beyond this machine).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>[address:]port</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--listen: expected a port or ADDRESS:PORT such as 9871 or 0.0.0.0:9871, got &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reaction time in seconds of the operator and of the person the router&apos;s predict nodes warn.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A gripper adapter, by name or as a semhap.gripper/1 file, whose model takes the place of the scene&apos;s grippers (default: the scene&apos;s own).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>gripper</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open this study (a study database) in study mode.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>STUDY.db</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>With --study: the participant to work with.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>With --participant: start their next step at once (for scripts and tests).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--start-step: name the participant with --participant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--participant: name the study with --study</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Who drives until you do: scripted, reactive or perceiving.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set a parameter of the perceiving operator&apos;s person (repeatable).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NAME=VALUE</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>UndoActions</name>
    <message>
        <source>Redo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Undo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Redo: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Undo: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::DevicesPanel</name>
    <message>
        <source>not bound</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connecting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>disconnected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 frames/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RTT %1 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>errors: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reconnects: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>armed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>disarmed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>retrying: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kind</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>URI</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Description</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>VID:PID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rescan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Present devices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arm all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disarm all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Real bands start disarmed: they output nothing until armed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Router devices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The URI to drive %1: pick a present device or type one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fall back to the virtual device virtual:%1; the run goes on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no transport</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of %2 armed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>e.g. udp:127.0.0.1:9000</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Its hand is not in this scene.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>latency %1 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 ch, %2 Hz (%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>An address that cannot be discovered, such as a band on the network or a pseudo-terminal, in one of these forms:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Devices</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::DistinctivenessView</name>
    <message>
        <source>The band whose messages are compared</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%1 (%2): %n message(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>The router has problems: once it compiles, this shows how far apart its messages feel on each band.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Its patterns cannot be compared: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No message plays on a band.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 and %2: %3 JND apart</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Only %1 plays on this band: there is nothing here to take it for.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>At intensity %1 no two of these messages are closer than 1 JND: a person tells them apart.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 and %2 (%3 JND)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Confusable, under 1 JND: %1. A person will take one for the other.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::Engine</name>
    <message>
        <source>nothing is loaded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the router has no device &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>nothing runs that sends to devices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>nothing runs that could be recorded</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::EventLogModel</name>
    <message>
        <source>%1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gripper</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Detector</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Message</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Phase</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Intensity</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::EventLogPanel</name>
    <message>
        <source>Follow</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Filter (detector, message, …)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keep the newest event in view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All grippers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Right</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All categories</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Confirmation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Exception</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All phases</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Begin</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Update</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>End</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Begin and end</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Events</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::HandDrive</name>
    <message>
        <source>Move the wrist away from you</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move the wrist towards you</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move the wrist to the left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move the wrist to the right</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Raise the wrist</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lower the wrist (it stops on what is below)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Turn the wrist left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Turn the wrist right</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close or open the grip</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Grip force up a step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Grip force down a step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch hand (scenes with two)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hold: move at a quarter of the speed</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::HelpActions</name>
    <message>
        <source>Key map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Every shortcut and drive key of the window</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Documentation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open the studio&apos;s manual</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The manual is not installed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read docs/studio.md in semhap&apos;s sources.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::ImportProgress</name>
    <message>
        <source>Importing %1 into %2…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::KeyMapDialog</name>
    <message>
        <source>Key map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Anywhere in the window</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>In the viewport (click it first)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>In the %1 panel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keys</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What they do</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::LiveRig</name>
    <message>
        <source>Live rig on %1
The rig draws its own scene.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::LiveRigDialog</name>
    <message>
        <source>Listen for a live rig</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>any free port</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Accept frames from other machines</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Listen on every network (0.0.0.0) instead of this machine only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>UDP port:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Listen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PORT</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;p&gt;Send contact frames (one JSON object per datagram, or an array of them) to this port; they run through the detectors, the router &lt;b&gt;%1&lt;/b&gt; and the devices like the simulation&apos;s.&lt;/p&gt;&lt;p&gt;To try it: &lt;code&gt;scripts/send-frames.py resources/traces/demo.jsonl --port %2&lt;/code&gt;&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Contact frames over UDP</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A robot&apos;s Foxglove server</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the semhap.topics/1 map of its topics</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Topic map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Topic maps (*.json);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Server:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Topic map:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;p&gt;The robot&apos;s topics become contact frames through the topic map, as a recording&apos;s do; they run through the detectors, the router &lt;b&gt;%1&lt;/b&gt; and the devices like the simulation&apos;s. When the robot restarts, the studio connects again.&lt;/p&gt;&lt;p&gt;On the robot: &lt;code&gt;ros2 launch foxglove_bridge foxglove_bridge_launch.xml&lt;/code&gt;&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::MainWindow</name>
    <message>
        <source>Network pose input is off: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not reset the run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Slower</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Faster</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Real time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pause the run and send every device to zero now (Esc, from anywhere)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stopped: every device was sent to zero.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Take the grippers over from the scripted operator (Ctrl+T); any key or pose input does it too</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open scene…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open scene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MuJoCo scenes (*.xml)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open router…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open router</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>semhap routers (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Preferences…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reset layout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About semhap</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;semhap studio&lt;/b&gt; %1&lt;/p&gt;&lt;p&gt;Semantic haptic feedback for robot teleoperation: contact forces become confirmations and exceptions, routed to patterns on wristbands.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not connect %1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The run reached its end. Reset to run it again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>semhap studio — %1 · %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>semhap studio</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not load scene %1 with router %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The run is paused while you audition a pattern.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Record</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open session…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open session</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Replay</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop recording</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Session saved to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not start recording</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not open session %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>semhap studio — replay of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not re-route the session</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not listen on udp:%1:%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Listening for a live rig on %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Listen for a live rig…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run another program&apos;s contact frames, sent over UDP, instead of the scene (Ctrl+L)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>semhap studio — live rig on %1 · %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Record the run into a new session in the sessions folder (Ctrl+Shift+R); again to stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n row(s) of the session break the stream rules and were skipped (semhap replay lists them)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>No gamepad connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gamepad: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gamepads are off: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Camera</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>3D mouse: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>3D mouse disconnected: the wrist stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The router editor keeps your edits, which are not what runs now: Apply runs them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Task done
The pile was finished after %1 s.
Carry on with the refilled box, or reset (%2) to start over.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 with %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not load scene %1 with gripper %2 and router %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gripper</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not load router %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not load scene %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not load gripper %1 into scene %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 runs with its own router, %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has a router of its own, %2: pick it under Router</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>semhap sessions and robot recordings (*.db *.mcap);;semhap sessions (*.db);;Robot recordings, rosbag2 in MCAP (*.mcap);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Topic map of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Topic maps (*.json);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not import %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import of %1 cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Imported %1: %n frame(s) into %2</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Publishing to Foxglove at %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot publish to Foxglove on port %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export session…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write the session replayed, or one you pick, as XDF for labs synchronised by the Lab Streaming Layer or as MCAP for Foxglove, PlotJuggler and Rerun</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Session to export</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>semhap sessions (*.db);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Exporting %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not export the session</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Session exported</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::ManualWindow</name>
    <message>
        <source>semhap studio manual</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back (Alt+Left)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forward (Alt+Right)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The studio&apos;s manual</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Search the page (Ctrl+F)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not found</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>semhap studio manual — %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::MetricSpec</name>
    <message>
        <source>Plugs inserted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plugs seated in the port.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time to insert</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The mean time from picking a plug up to seating it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Collisions with the port</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Times the plug pushed on the port&apos;s face beside the opening.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Peak insertion force</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The highest force on the port during the run.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plug pick-ups</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Times a plug was lifted from where it was laid out.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plugs dropped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plugs let go of after a pick-up without being seated.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cues taken in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cues the perceiving operator felt on a band or saw on the overlay.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cues misread</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cues the perceiving operator took for a message of the other meaning: a warning for a confirmation, or the other way round.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Warnings ignored</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Warnings the perceiving operator felt and did not answer, for how seldom that hand&apos;s warnings had been right.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left reliance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The share of the left hand&apos;s warnings the perceiving operator answers now.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Right reliance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The share of the right hand&apos;s warnings the perceiving operator answers now.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulated time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulated time so far.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wall time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Real time so far.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Real-time factor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulated seconds per real second.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The task that runs.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Router</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The router the run was loaded with.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Operator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Who drives the grippers when you do not.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Seed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The seed of the operator and of a laid-out scene.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Completion time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>When the pile was first finished: every cube transferred or broken (box_and_block).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cubes transferred</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cubes that arrived where the task wants them, once per trip.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cubes broken</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cubes that fractured under the fingertips.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cubes dropped (slipped out)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Grasps that ended while the hand still gripped, after a lift: the cube slipped out.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Grasps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Grasps begun.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Grasps per transfer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Grasps per cube transferred: 1 is one grasp for each.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Average grasp force</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The mean force of both fingertips over every moment of every grasp.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Average peak grasp force</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The mean over grasps of the highest force during each.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Warning lead time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How long before a break its warning was first felt, on average.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Breaks warned</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The share of breaks a felt warning came before.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Breaks warned in time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The share of breaks warned at least a reaction time before: the warnings a person could act on.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Containers dropped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Times the held container left the left fingertips and fell (bimanual).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drop warning lead time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How long before a container drop its warning was first felt, on average (bimanual).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drops warned</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The share of container drops a felt warning came before (bimanual).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drops warned in time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The share of container drops warned at least a reaction time before (bimanual).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Containers set down</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Times the holding hand set the full container down on its base to be emptied (bimanual).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Transfers per container cycle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cubes transferred per container cycle, which a drop or a set-down ends (bimanual).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Confirmations felt per grasp</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Confirmations felt per real grasp: 1 is one per grasp, more is chatter, 0 without feedback.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Slip episodes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Times the container slid in the left fingertips (bimanual).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Warnings felt per slip episode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Warnings felt on the left hand per slip: above 1, warnings came that no slip answered (bimanual).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Breaks warned by onset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The share of breaks whose warning began within the horizon before, in time to act: a warning on all along does not count.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Right warnings borne out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The share of the right hand&apos;s warnings a break, or the grip crossing the break line, followed within the horizon: the rest were false alarms.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Right warning duty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The share of grasping time a warning was felt on the right hand.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drops warned by onset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The share of container drops whose warning began within the horizon before, in time to act (bimanual).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left warnings borne out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The share of the left hand&apos;s warnings a drop or a slip followed within the horizon: the rest were false alarms (bimanual).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left warning duty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The share of the time the container was held that a warning was felt (bimanual).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cube box refills</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Times the cube box was refilled.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Area cleaned (plates)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cells cleaned, in plates&apos; worth: above 1 when more than a plate was cleaned.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time to clean</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>When every cell of the first plate was first clean.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plates cleaned</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Times every cell of a plate was clean at once.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plates broken</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plates broken by pressing above 40 N.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Peak force</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The highest press of the sponge on the plate.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time above the safe force</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The time the press was above the safe 25 N.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Average press force</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The mean press while the sponge pressed on the plate.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Warnings felt</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Warnings felt on the wiping hand.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sponge stiffened at</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>When the sponge&apos;s holder stiffened.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Blocks stacked</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Levels the placements added to the tower.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Towers built</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Towers stacked five blocks high.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tallest tower</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The most levels the tower had at once.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Topples</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Times the tower lost levels without a block being taken off it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Blocks dropped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lifted blocks let go of anywhere but on top of the tower.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time per level</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The mean time from lifting a block to the level it adds.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::MetricsPanel</name>
    <message>
        <source>No metrics yet: they appear while a task runs.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>n/a</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>yes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1×</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a count</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a ratio</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>times real time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>seconds of simulated time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>newtons (N)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a share, 0 to 100 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1
In exports: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1
In %2; in exports: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Higher is better.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lower is better.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Task metrics</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::NodeInspector</name>
    <message>
        <source>Pattern</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Track %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Waveform</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Select a node in the tree</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Description</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Channels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>* drives every channel of the model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Changing the type to a combinator keeps this waveform as its input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gain</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>To</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Amplitude</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Duty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>High</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Low</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Divide by</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Minimum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Maximum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Its inputs are the children in the tree.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Frequency</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Phase</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Width</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Starts from</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::NotesPage</name>
    <message>
        <source>Notes</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::NumberEdit</name>
    <message>
        <source>A fixed value, or a live parameter of the pattern</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>× </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gain: the value is gain × parameter + offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>+ </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Offset: the value is gain × parameter + offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>through a curve (edit it in the JSON tab)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>value</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::ParamForm</name>
    <message>
        <source>(none)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(any)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(automatic)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(default: %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(default)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not a parameter of this node: clear it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>current value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>peak since begin</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>fixed value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Where the envelope starts: the track&apos;s value when it began, its peak, or a fixed value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not understood; nothing was changed</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::PatternAuditioner</name>
    <message>
        <source>There is no device to play on.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::PatternDocument</name>
    <message>
        <source>Edit %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::PatternPreview</name>
    <message>
        <source>all channels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>time since begin (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>commanded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>predicted output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> end</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::PlotPanel</name>
    <message>
        <source>Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Freeze the view; data keep being recorded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Live</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Follow the newest data again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Width of the live time window</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Window:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save the visible time range as CSV</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export PNG…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save the plots as an image</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Click to place the cursor; when paused, drag to pan (Shift+drag moves the cursor) and use the wheel to zoom</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>pipeline time (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>right gripper</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>left gripper</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: force</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>F (N)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>F (sum)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2 N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: contacts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>N (contacts)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>t = %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: F %2 N (left %3, right %4), N %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot write %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export Plots as CSV</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export Plots as PNG</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export PNG</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>left.f (finger)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>right.f (finger)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2 (end %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plots</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::PoseInput</name>
    <message>
        <source>%1 bytes, larger than the limit of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not JSON: %1 at byte %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected a JSON object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>key &apos;hand&apos;: expected &quot;left&quot; or &quot;right&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>key &apos;pos&apos;: expected an array of 3 numbers (metres)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>key &apos;pos&apos;: %1 is beyond %2 m from the origin (positions are in metres)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>key &apos;quat&apos;: expected an array of 4 numbers [w, x, y, z], not all 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>key &apos;yaw&apos;: expected a number (radians)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>key &apos;grip&apos;: expected a number (newtons)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown key &apos;%1&apos; (expected hand, pos, quat or yaw, grip)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>key &apos;hand&apos; is missing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>keys &apos;quat&apos; and &apos;yaw&apos;: give one of them</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>key &apos;hand&apos;: this scene has no %1 gripper</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>key &apos;pos&apos; is needed before the %1 hand can be turned on its own</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>datagram %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>System language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Interface language:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Where recordings go</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sessions folder:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>General</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Driving</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(none)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left stick →</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left stick ←</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left stick ↓</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left stick ↑</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Right stick →</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Right stick ←</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Right stick ↓</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Right stick ↑</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left trigger</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left trigger, reversed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Right trigger</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Right trigger, reversed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Guide</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left stick press</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Right stick press</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left shoulder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Right shoulder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>D-pad ↑</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>D-pad ↓</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>D-pad ←</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>D-pad →</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> cm/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How fast the wrist moves with a key held or a stick pushed all the way; Shift moves at a quarter of it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drive with a gamepad</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How far a stick may rest off-centre without moving the wrist</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Away / toward:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Right / left:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Up / down:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Turn:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tilt:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Roll:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Grip:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close / open:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch hand:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Grip force +5 N:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Grip force −5 N:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hand back (Drive off):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Next camera view:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stick dead zone:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Default mapping</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gamepad</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drive with a 3D mouse (through spacenavd)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>3D mouse</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dead zone:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wrist speed:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Publish to Foxglove on port</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Viewers:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A new language rebuilds the window where it is, with its layout; the run, a recording, the devices and your edits go on. Recordings go to the sessions folder from the next one on. Foxglove on this computer watches the run live at ws://localhost:PORT (Open connection → Foxglove WebSocket).</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::QuestionnaireWindow</name>
    <message>
        <source>Questionnaire</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>At the end of the study</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>After: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Thank you!

Please tell the experimenter that you are done.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Question %1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Finish</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Next</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enter: close</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Your answer could not be stored: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Please set each of the six scales.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Please choose one of the points.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tab: next scale · ← →: set it · Enter: next page · Backspace: back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1–%1: choose · ← →: move · Enter: next page · Backspace: back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>↑ ↓: choose · Ctrl+↑ ↓: move it · Enter: next page · Backspace: back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ctrl+Enter: next page · Alt+←: back</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::RankingPage</name>
    <message>
        <source>Put the conditions in order: the one you liked most at the top, the one you liked least at the bottom.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move down</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::ReplayBar</name>
    <message>
        <source>Play or pause the replay</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Session time: click or drag to scrub</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Session seconds per real second</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1×</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run the recorded contact frames through the router in the router editor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recorded router</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the events and device frames the session recorded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close replay</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Play</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 / %2 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Showing: re-routed through %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Showing: recorded with %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown date</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>live rig</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Notes: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recorded by: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Operator: %1, seed %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Router: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Started: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ended: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ended: never closed (the recording was cut off)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Router: %1, edited (it routes differently from %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Re-route</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::RouterEditor</name>
    <message>
        <source>Auto-apply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Send every edit that compiles to the running session</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not connected: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Router</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New (empty)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New from preset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open router</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>semhap routers (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save self-contained…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arrange</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lay the nodes out in columns: detectors, logic, patterns, devices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the whole graph</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Copy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paste</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Make this graph the running router</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connected %1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a valid id (non-empty, no &apos;:&apos; or spaces)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>there is already a node &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Copied %n node(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>clipboard</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing to paste: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save self-contained router</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save router</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>untitled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not applied: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Applied: the running session uses this router now.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rename pattern</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Applied: the replay was re-routed through this router.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Applied: the run waiting behind the replay uses this router.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New router.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New router from the preset %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — not saved to a file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — changed since it was saved</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save or Save as… writes it to a file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — changed from the preset, not saved to a file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — preset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Distinctiveness</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How far apart the messages on each band feel, in just-noticeable differences</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::RouterInspector</name>
    <message>
        <source>Select a node to edit its parameters.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n nodes selected.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>The name events and devices carry</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (your file)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::RouterPalette</name>
    <message>
        <source>Drag a node type onto the canvas, or double-click it</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::RouterScene</name>
    <message>
        <source>an output connects to an input, not to another output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an input connects to an output, not to another input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>output %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::RunReadouts</name>
    <message>
        <source>Recording to %1 (%2 dropped)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>t = %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Foxglove: %n viewer(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Published at %1: %2 message(s) sent, %3 dropped for slow viewers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Replay: nobody drives</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>replay</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1× real time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>paused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>You are driving</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Operator: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Live rig on %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 frames/s, jitter %2 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>paused: %n frame(s) held</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source> · %n malformed</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Malformed datagram: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Latest malformed datagram: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Devices: %1 virtual, %2 connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, %1 connecting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, %1 disconnected</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::RunToolBar</name>
    <message>
        <source>Simulation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulated seconds per real second (Ctrl+- / Ctrl++)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Real time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1× speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scene:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The task to simulate, or a live rig&apos;s frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Live rig…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Router:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Session name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Names the next recording&apos;s file (empty: scene, router and time); File → Preferences says where it goes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Session notes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kept with the next recording (participant, condition, …)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gripper</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scene&apos;s own</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Other file…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open gripper adapter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gripper adapters (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gripper: %1
The scene&apos;s own grippers, or a gripper adapter&apos;s model in their place</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the scene&apos;s own</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Which feedback design turns events into patterns</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::SessionExport</name>
    <message>
        <source>XDF for LSL labs, session time with clock offsets (*.xdf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>XDF for LSL labs, on LSL&apos;s clock (*.xdf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MCAP for Foxglove, PlotJuggler and Rerun (*.mcap)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export session</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::SessionReplay</name>
    <message>
        <source>Replay: a live rig&apos;s session has no scene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Replay: no scene state recorded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>its scene states do not fit scene %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Replay: the scene cannot be shown (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Replay: a robot&apos;s recording has no scene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Replay</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::SimViewport</name>
    <message>
        <source>Reset camera</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Waiting for the simulation…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No scene loaded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>You are driving (right hand)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>You are driving (left hand)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Grip: closed, %1 N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Grip: open (closes to %1 N)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>W A S D move · R F up/down · Q E turn · Space grip · +/- force</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tab: switch hand</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulated operator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Click here and press W A S D to drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Across the jaws</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>From the top</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>From the side</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Follow the hand</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Resting on what is below: the wrist stops here</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wrist %1 cm above the surface below</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>W goes %1, D goes %2 · 1–4 camera</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Grip: %1 N asked, applied at the run&apos;s next step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Grip: opening, %1 N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Grip: %1 N of %2 N, tightening on what the pads touch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Grip: %1 N of %2 N, closing slowly until both pads touch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Contact forces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back to the default view (%1; Home in the viewport)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show contact forces as arrows in the viewport (%1)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::SpaceMouseInput</name>
    <message>
        <source>3D mouse</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::Studio</name>
    <message>
        <source>%1: could not write the screenshot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Some of what you left open could not be opened again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Your work is not being saved</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: no participant &apos;%2&apos;</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::StudyDocument</name>
    <message>
        <source>The break is over.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The trial that ran could not be stored as aborted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no study is open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>choose a participant first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a trial runs already</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the break is on: skip it to go on at once</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the next step is no practice round or trial</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The end of %1 could not be stored</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: done.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no trial runs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 was aborted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 could not be stored as aborted</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>until %n transfer(s) or %1 s</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>until %n transfer(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Practice — %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Trial %1 of %2 — %3 (%4 s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Questionnaire after %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Final questionnaire</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All steps done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: cannot create the folder</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::StudyMenu</name>
    <message>
        <source>Stud&amp;y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New study…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open study…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export results…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close study</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start a study from a protocol: participants, their orders of conditions, timed trials and questionnaires</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write the study&apos;s results into a folder: measures.csv (tidy, for R or pandas), trials.csv, answers.csv, and the analysis&apos; report with a box plot per measure</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New study: its protocol</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>semhap study protocols (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New study: where to keep it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>semhap studies (*.db)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not create the study</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open study</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>semhap studies (*.db);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not open the study %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export the study&apos;s results into</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not export the study&apos;s results</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Exported %1 files into %2: measures.csv, trials.csv, answers.csv and %3/report.md</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 runs. Closing the study aborts it: it will not count and is due again when the study is opened again.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::StudyPanel</name>
    <message>
        <source>running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>aborted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>invalid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>interrupted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Practice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Trial %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Questionnaire</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Final questionnaire</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No study is open. A study runs a protocol&apos;s conditions, trials and questionnaires with each participant and keeps everything in one file.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>e.g. P01</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A participant&apos;s ID: 1 to 32 letters, digits, _ . or -. No names needed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Participants</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>State</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Skip break</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Abort…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>End the trial now; it does not count and is due again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mark invalid…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The done trial chosen in the list does not count: it is due again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add a participant, or choose one.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Order of %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Attempt %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>answered</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>next</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Now: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paused. </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left of the trial</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>at most %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of %2 transfers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Practice so far</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Next: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Break before the next trial</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose a participant.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This participant has done every step.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start when the participant is ready.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Resume</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not start %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Abort the trial</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Why is %1 aborted? It will not count and is due again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not store %1 as aborted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mark the trial invalid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Why does this trial not count? It is kept, marked invalid, and is due again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not mark the trial invalid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Questionnaire opens it for the participant, in a window of its own.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>at %1× real time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No participant chosen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Study</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::TlxPage</name>
    <message>
        <source>Mental demand</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How mentally demanding was the task?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Very low</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Very high</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Physical demand</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How physically demanding was the task?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Temporal demand</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How hurried or rushed was the pace of the task?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Performance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How successful were you in accomplishing what you were asked to do?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Perfect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Failure</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Effort</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How hard did you have to work to accomplish your level of performance?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Frustration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How insecure, discouraged, irritated, stressed, and annoyed were you?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How was the task you just did? Set each of the six scales.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>–</source>
        <comment>a TLX scale not set yet</comment>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::UserPatterns</name>
    <message>
        <source>A pattern needs a name.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos; cannot name a file: a pattern&apos;s name may not contain &apos;/&apos; or &apos;\&apos; or begin with &apos;.&apos;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos; is the name of a built-in pattern: choose another.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Another of your patterns is named &apos;%1&apos;: choose another name.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::WaveformDesigner</name>
    <message numerus="yes">
        <source>%n point(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Playing on %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Releasing on %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> — disarmed: arm it in the Devices panel to feel it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open pattern</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not open %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save as…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Make an editable copy of this pattern</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import an Apple AHAP or a Meta .haptic file as a new pattern</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export the pattern as AHAP or .haptic (docs/convert.md)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Library</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Built-in patterns (locked) and your own, from %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add track</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A new track, driving every channel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Give the selected track an attack, a sustain or a release</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Attack</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sustain</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Release</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Another input of the selected sum, product or sequence</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove the selected node</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>JSON</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The device model the pattern is for; the preview predicts its output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The intensity the pattern begins with (preview and audition)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hold</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Intensity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>End at</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Where the audition plays: a bound device of the run (the run pauses), or a virtual one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Audition</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Begin the pattern on the device now (again: restart it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>End</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>End the pattern: its release plays</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Send the device to zero now (Esc stops everything)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Audition on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Built-in, read-only: duplicate it to edit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>virtual (audition only)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save pattern</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Patterns (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not save %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import haptic file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not import %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export pattern</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not export %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt; is built in and read-only. &lt;b&gt;Duplicate&lt;/b&gt; it to edit a copy.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New pattern</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> — not saved</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pattern %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Track %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edit JSON</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unknown device model &apos;%1&apos; (built-in: %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot audition</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown device model %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot audition on %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Waveform tree</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Valid pattern</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>When the preview and the audition end the pattern (its release starts)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Preview and audition without an end: the sustain goes on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not save %1 as %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved %1, but could not remove %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Renamed %1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pattern</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New, open, save as, import and export</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not saved yet: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Patterns</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open a pattern, an AHAP, a .haptic or an HJIF file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Patterns and haptic files (*.json *.ahap *.haptic *.hjif)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Haptic files (*.ahap *.haptic *.hjif)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apple AHAP (*.ahap);;Meta Haptics (*.haptic);;MPEG haptics (*.hjif)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>semhap::Workspace</name>
    <message>
        <source>%1: the file as it was is kept as %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 stays unbound: the router that runs has no %2 device &apos;%3&apos;</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>

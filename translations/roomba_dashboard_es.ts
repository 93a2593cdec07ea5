<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="es">
<context>
    <name>BatteryCheck</name>
    <message>
        <source>the voltage %1 V is outside what its pack can have (%2 to %3 V)</source>
        <translation>la tensión de %1 V está fuera de lo que puede tener su batería (de %2 a %3 V)</translation>
    </message>
    <message>
        <source>the charge %1 mAh is above the capacity %2 mAh</source>
        <translation>la carga de %1 mAh supera la capacidad de %2 mAh</translation>
    </message>
    <message>
        <source>the charge jumped from %1 % to %2 % in %3 s</source>
        <translation>la carga saltó del %1 % al %2 % en %3 s</translation>
    </message>
    <message>
        <source>Battery reading cannot be true: %1. It is left out of the gauges and plots; if it goes on, check the battery&apos;s seating and contacts.</source>
        <translation>La lectura de la batería no puede ser cierta: %1. Se omite en los indicadores y las gráficas; si continúa, compruebe el asiento y los contactos de la batería.</translation>
    </message>
</context>
<context>
    <name>BatteryHealth</name>
    <message>
        <source>holds %1 of the %2 mAh it claims (%3 %)</source>
        <translation>retiene %1 de los %2 mAh que declara (%3 %)</translation>
    </message>
    <message>
        <source>resistance %1 mΩ, %2 times a new pack&apos;s</source>
        <translation>resistencia de %1 mΩ, %2 veces la de una batería nueva</translation>
    </message>
    <message>
        <source>it needs a drive started and stopped a few times, and part of a discharge or a charge</source>
        <translation>necesita arrancar y detener la marcha unas cuantas veces, y parte de una descarga o de una carga</translation>
    </message>
    <message>
        <source>; </source>
        <translation>; </translation>
    </message>
    <message>
        <source>; capacity not measured yet</source>
        <translation>; capacidad aún sin medir</translation>
    </message>
    <message>
        <source>Good</source>
        <translation>Buena</translation>
    </message>
    <message>
        <source>Worn</source>
        <translation>Gastada</translation>
    </message>
    <message>
        <source>Replace</source>
        <translation>Cambiar</translation>
    </message>
    <message>
        <source>Not measured yet</source>
        <translation>Aún sin medir</translation>
    </message>
    <message>
        <source>%1 % of a cycle seen, %2 resistance samples</source>
        <translation>%1 % de un ciclo visto, %2 muestras de resistencia</translation>
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
        <translation>batería casi agotada (%1): el robot sale solo de Safe o Full bajo carga; póngalo a cargar</translation>
    </message>
    <message>
        <source>Charging fault: the robot will not charge. Usually the charging contacts are dirty (on the robot or the dock), the supply is not the robot&apos;s own, or the pack was run deeply flat (Safe or Full left on the dock drains it). Clean the contacts, reseat the pack, then reset the charger: hold Spot and Dock together for 10 seconds, and put it back on the dock.</source>
        <translation>Fallo de carga: el robot no carga. Normalmente los contactos de carga están sucios (en el robot o en la base), la fuente de alimentación no es la del robot, o la batería se descargó a fondo (Safe o Full en la base la descarga). Limpie los contactos, vuelva a colocar la batería y reinicie el cargador: mantenga pulsados Spot y Dock a la vez durante 10 segundos, y vuelva a ponerlo en la base.</translation>
    </message>
    <message>
        <source>%1: %2 (%3)</source>
        <translation>%1: %2 (%3)</translation>
    </message>
    <message>
        <source>; measured %1</source>
        <translation>; medido el %1</translation>
    </message>
    <message>
        <source>; the charge is estimated from voltage since the robot booted</source>
        <translation>; la carga se estima a partir de la tensión desde que arrancó el robot</translation>
    </message>
    <message>
        <source>; capacity so far: %1</source>
        <translation>; capacidad hasta ahora: %1</translation>
    </message>
</context>
<context>
    <name>BitName</name>
    <message>
        <source>Advance</source>
        <translation>Avanzar</translation>
    </message>
    <message>
        <source>Baud Rate Change (active low)</source>
        <translation>Cambio de velocidad en baudios (activo bajo)</translation>
    </message>
    <message>
        <source>Bump Left</source>
        <translation>Parachoques izquierdo</translation>
    </message>
    <message>
        <source>Bump Right</source>
        <translation>Parachoques derecho</translation>
    </message>
    <message>
        <source>Center Left</source>
        <translation>Central izquierdo</translation>
    </message>
    <message>
        <source>Center Right</source>
        <translation>Central derecho</translation>
    </message>
    <message>
        <source>Clean</source>
        <translation>Limpiar</translation>
    </message>
    <message>
        <source>Clock</source>
        <translation>Reloj</translation>
    </message>
    <message>
        <source>Day</source>
        <translation>Día</translation>
    </message>
    <message>
        <source>Digital Input 0</source>
        <translation>Entrada digital 0</translation>
    </message>
    <message>
        <source>Digital Input 1</source>
        <translation>Entrada digital 1</translation>
    </message>
    <message>
        <source>Digital Input 2</source>
        <translation>Entrada digital 2</translation>
    </message>
    <message>
        <source>Digital Input 3</source>
        <translation>Entrada digital 3</translation>
    </message>
    <message>
        <source>Dock</source>
        <translation>Base</translation>
    </message>
    <message>
        <source>Front Left</source>
        <translation>Delantero izquierdo</translation>
    </message>
    <message>
        <source>Front Right</source>
        <translation>Delantero derecho</translation>
    </message>
    <message>
        <source>Home Base</source>
        <translation>Base de carga</translation>
    </message>
    <message>
        <source>Hour</source>
        <translation>Hora</translation>
    </message>
    <message>
        <source>Internal Charger</source>
        <translation>Cargador interno</translation>
    </message>
    <message>
        <source>Left</source>
        <translation>Izquierdo</translation>
    </message>
    <message>
        <source>Left Wheel</source>
        <translation>Rueda izquierda</translation>
    </message>
    <message>
        <source>Low Side Driver 0</source>
        <translation>Controlador de lado bajo 0</translation>
    </message>
    <message>
        <source>Low Side Driver 1</source>
        <translation>Controlador de lado bajo 1</translation>
    </message>
    <message>
        <source>Low Side Driver 2</source>
        <translation>Controlador de lado bajo 2</translation>
    </message>
    <message>
        <source>Main Brush</source>
        <translation>Cepillo principal</translation>
    </message>
    <message>
        <source>Minute</source>
        <translation>Minuto</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Reproducir</translation>
    </message>
    <message>
        <source>Right</source>
        <translation>Derecho</translation>
    </message>
    <message>
        <source>Right Wheel</source>
        <translation>Rueda derecha</translation>
    </message>
    <message>
        <source>Schedule</source>
        <translation>Programación</translation>
    </message>
    <message>
        <source>Side Brush</source>
        <translation>Cepillo lateral</translation>
    </message>
    <message>
        <source>Spot</source>
        <translation>Spot</translation>
    </message>
    <message>
        <source>Wheel Drop Caster</source>
        <translation>Caída de rueda loca</translation>
    </message>
    <message>
        <source>Wheel Drop Left</source>
        <translation>Caída de rueda izquierda</translation>
    </message>
    <message>
        <source>Wheel Drop Right</source>
        <translation>Caída de rueda derecha</translation>
    </message>
</context>
<context>
    <name>BoundedFile</name>
    <message>
        <source>not a regular file but a named pipe</source>
        <translation>no es un archivo normal, sino una tubería con nombre</translation>
    </message>
    <message>
        <source>not a regular file but a folder</source>
        <translation>no es un archivo normal, sino una carpeta</translation>
    </message>
    <message>
        <source>not a regular file but a device</source>
        <translation>no es un archivo normal, sino un dispositivo</translation>
    </message>
    <message>
        <source>not a regular file</source>
        <translation>no es un archivo normal</translation>
    </message>
    <message>
        <source>%1, larger than the %2 this program reads of such a file</source>
        <translation>%1, más que los %2 que este programa lee de un archivo así</translation>
    </message>
    <message>
        <source>larger than the %1 this program reads of such a file</source>
        <translation>más que los %1 que este programa lee de un archivo así</translation>
    </message>
    <message>
        <source>%1 bytes</source>
        <translation>%1 bytes</translation>
    </message>
</context>
<context>
    <name>BrokerActions</name>
    <message>
        <source>Connect to &amp;broker…</source>
        <translation>Conectar con el &amp;bróker…</translation>
    </message>
    <message>
        <source>&amp;Disconnect from broker</source>
        <translation>&amp;Desconectar del bróker</translation>
    </message>
    <message>
        <source>&amp;Fleet view	Ctrl+Shift+F</source>
        <translation>Vista de la &amp;flota	Ctrl+Mayús+F</translation>
    </message>
    <message>
        <source>Fleet view — Roomba Dashboard</source>
        <translation>Vista de la flota — Roomba Dashboard</translation>
    </message>
    <message>
        <source>%1. Type the password again, or another user name.</source>
        <translation>%1. Escriba de nuevo la contraseña, u otro nombre de usuario.</translation>
    </message>
    <message>
        <source>Connecting again to %1, the class of the last session.</source>
        <translation>Conectando de nuevo con %1, la clase de la última sesión.</translation>
    </message>
    <message>
        <source>Last session: the class on %1 as &quot;%2&quot;. Reconnect… asks for the password.</source>
        <translation>Última sesión: la clase en %1 como «%2». Reconectar… pide la contraseña.</translation>
    </message>
</context>
<context>
    <name>BrokerDialog</name>
    <message>
        <source>Connect to broker</source>
        <translation>Conectar con el bróker</translation>
    </message>
    <message>
        <source>&amp;Host:</source>
        <translation>&amp;Host:</translation>
    </message>
    <message>
        <source>&amp;Port:</source>
        <translation>&amp;Puerto:</translation>
    </message>
    <message>
        <source>anonymous</source>
        <translation>anónimo</translation>
    </message>
    <message>
        <source>&amp;User:</source>
        <translation>&amp;Usuario:</translation>
    </message>
    <message>
        <source>Pass&amp;word:</source>
        <translation>Contra&amp;seña:</translation>
    </message>
    <message>
        <source>&amp;Remember the password (kept in plain text in the settings)</source>
        <translation>&amp;Recordar la contraseña (guardada en texto plano en la configuración)</translation>
    </message>
    <message>
        <source>&amp;TLS</source>
        <translation>&amp;TLS</translation>
    </message>
    <message>
        <source>the system&apos;s certificates</source>
        <translation>los certificados del sistema</translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation>&amp;Examinar…</translation>
    </message>
    <message>
        <source>&amp;CA file:</source>
        <translation>Archivo &amp;CA:</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Conectar</translation>
    </message>
    <message>
        <source>CA certificate</source>
        <translation>Certificado CA</translation>
    </message>
    <message>
        <source>Certificates (*.pem *.crt);;All files (*)</source>
        <translation>Certificados (*.pem *.crt);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>Enter the broker&apos;s host name or address.</source>
        <translation>Introduzca el nombre de host o la dirección del bróker.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a host name.</source>
        <translation>«%1» no es un nombre de host.</translation>
    </message>
    <message>
        <source>A password needs a user name.</source>
        <translation>Una contraseña necesita un nombre de usuario.</translation>
    </message>
    <message>
        <source>The CA file %1 cannot be read.</source>
        <translation>No se puede leer el archivo CA %1.</translation>
    </message>
</context>
<context>
    <name>ByteInspector</name>
    <message>
        <source>Resume</source>
        <translation>Reanudar</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pausa</translation>
    </message>
    <message>
        <source>Stop scrolling new bytes into view; they are still recorded</source>
        <translation>Deja de desplazar los bytes nuevos a la vista; se siguen registrando</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Borrar</translation>
    </message>
    <message>
        <source>Forget every entry and reset the counts</source>
        <translation>Olvida todas las entradas y pone a cero los contadores</translation>
    </message>
    <message>
        <source>Hex</source>
        <translation>Hex</translation>
    </message>
    <message>
        <source>Show bytes in hexadecimal instead of decimal</source>
        <translation>Muestra los bytes en hexadecimal en lugar de decimal</translation>
    </message>
    <message>
        <source>Byte log</source>
        <translation>Registro de bytes</translation>
    </message>
    <message>
        <source>Raw bytes to send, e.g. 128 131 or 0x80 0x83</source>
        <translation>Bytes sin procesar para enviar, p. ej. 128 131 o 0x80 0x83</translation>
    </message>
    <message>
        <source>Raw bytes to send</source>
        <translation>Bytes sin procesar para enviar</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>Enviar</translation>
    </message>
    <message>
        <source>Check the bytes and send them to the robot</source>
        <translation>Comprueba los bytes y los envía al robot</translation>
    </message>
    <message numerus="yes">
        <source>%Ln entry · TX %1 B · RX %2 B</source>
        <translation>
            <numerusform>%Ln entrada · TX %1 B · RX %2 B</numerusform>
            <numerusform>%Ln entradas · TX %1 B · RX %2 B</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%Ln entries · TX %1 B · RX %2 B</source>
        <translation>
            <numerusform>%Ln entrada · TX %1 B · RX %2 B</numerusform>
            <numerusform>%Ln entradas · TX %1 B · RX %2 B</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source> · paused, %Ln new</source>
        <translation>
            <numerusform> · en pausa, %Ln nueva</numerusform>
            <numerusform> · en pausa, %Ln nuevas</numerusform>
        </translation>
    </message>
    <message>
        <source> · paused</source>
        <translation> · en pausa</translation>
    </message>
    <message>
        <source>Clock time</source>
        <translation>Hora del reloj</translation>
    </message>
    <message>
        <source>Since connect</source>
        <translation>Desde la conexión</translation>
    </message>
    <message>
        <source>Time format</source>
        <translation>Formato de hora</translation>
    </message>
    <message>
        <source>Show each entry&apos;s time of day, or the seconds since the link was opened</source>
        <translation>Mostrar la hora de cada entrada, o los segundos desde que se abrió el enlace</translation>
    </message>
</context>
<context>
    <name>CalibrationDrive</name>
    <message>
        <source>The run was stopped before the end.</source>
        <translation>La marcha se detuvo antes del final.</translation>
    </message>
    <message>
        <source>A recording cannot be driven: connect to the robot.</source>
        <translation>Una grabación no se puede conducir: conéctate al robot.</translation>
    </message>
    <message>
        <source>The robot sends no data: connect to it and wait until it streams.</source>
        <translation>El robot no envía datos: conéctate a él y espera a que transmita.</translation>
    </message>
    <message>
        <source>Say first whether this is a Roomba 500 or a Create 2: their encoders read the other way round.</source>
        <translation>Di primero si es un Roomba 500 o un Create 2: sus codificadores se leen al revés.</translation>
    </message>
    <message>
        <source>A run is already under way.</source>
        <translation>Ya hay una marcha en curso.</translation>
    </message>
    <message>
        <source>Stopped.</source>
        <translation>Detenido.</translation>
    </message>
    <message>
        <source>The robot did not enter Safe mode: is it on its dock, or a wheel lifted?</source>
        <translation>El robot no entró en modo Safe: ¿está en su base, o tiene una rueda levantada?</translation>
    </message>
    <message>
        <source>The robot bumped into something: clear its path and run the step again.</source>
        <translation>El robot chocó con algo: despeja su camino y repite el paso.</translation>
    </message>
    <message>
        <source>A cliff sensor saw a drop: move the robot away from the edge and run the step again.</source>
        <translation>Un sensor de desnivel vio un borde: aparta el robot del borde y repite el paso.</translation>
    </message>
    <message>
        <source>A wheel dropped: put the robot on the floor and run the step again.</source>
        <translation>Una rueda cayó: pon el robot en el suelo y repite el paso.</translation>
    </message>
    <message>
        <source>A cliff sensor reads a dark floor (its signal low but not near 0, no wheel dropped): move the robot to a lighter floor and run the step again.</source>
        <translation>Un sensor de desnivel ve un suelo oscuro (su señal es baja pero no cercana a 0, ninguna rueda caída): lleva el robot a un suelo más claro y repite el paso.</translation>
    </message>
    <message>
        <source>The run did not reach its end in %1 s: the robot counted %2 of it. Is a wheel slipping or held? Check the floor and the wheels, and run the step again.</source>
        <translation>La pasada no llegó a su fin en %1 s: el robot contó %2 de ella. ¿Patina o está retenida una rueda? Revisa el suelo y las ruedas y repite el paso.</translation>
    </message>
    <message>
        <source>The robot did not report its angle after the run: run the step again.</source>
        <translation>El robot no informó de su ángulo tras la pasada: repite el paso.</translation>
    </message>
</context>
<context>
    <name>CalibrationWizard</name>
    <message>
        <source>Calibrate odometry: %1</source>
        <translation>Calibrar la odometría: %1</translation>
    </message>
    <message>
        <source>&lt; &amp;Back</source>
        <translation>&lt; &amp;Atrás</translation>
    </message>
    <message>
        <source>&amp;Next &gt;</source>
        <translation>&amp;Siguiente &gt;</translation>
    </message>
    <message>
        <source>&amp;Stop</source>
        <translation>&amp;Parar</translation>
    </message>
    <message>
        <source>Stop the robot (also Esc or Space)</source>
        <translation>Parar el robot (también Esc o Espacio)</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>&amp;Cerrar</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>&amp;Drive straight</source>
        <translation>&amp;Avanzar recto</translation>
    </message>
    <message>
        <source>from the tape, in mm</source>
        <translation>según la cinta métrica, en mm</translation>
    </message>
    <message>
        <source>optional: mm to the left (+) or right (-) of the line</source>
        <translation>opcional: mm a la izquierda (+) o a la derecha (-) de la línea</translation>
    </message>
    <message>
        <source>Distance:</source>
        <translation>Distancia:</translation>
    </message>
    <message>
        <source>It really drove:</source>
        <translation>Avanzó de verdad:</translation>
    </message>
    <message>
        <source>Off the line at the end:</source>
        <translation>Fuera de la línea al final:</translation>
    </message>
    <message>
        <source>Put the robot on a hard, clear floor with room ahead, and mark the floor under the centre of its front edge. It enters Safe mode and drives ahead by its wheel encoders, slowly, then stops. Measure with a tape from the mark to where the front edge stopped and type it in. If it ended off the straight line, say how far: that tells a left wheel from a right one.</source>
        <translation>Pon el robot en un suelo duro y despejado con espacio delante, y marca el suelo bajo el centro de su borde delantero. Entra en modo Safe, avanza despacio según los codificadores de sus ruedas y se detiene. Mide con una cinta desde la marca hasta donde se detuvo el borde delantero y escríbelo. Si terminó fuera de la línea recta, indica cuánto: eso distingue la rueda izquierda de la derecha.</translation>
    </message>
    <message>
        <source> turns</source>
        <translation> vueltas</translation>
    </message>
    <message>
        <source>S&amp;pin</source>
        <translation>&amp;Girar</translation>
    </message>
    <message>
        <source>in degrees, e.g. 715</source>
        <translation>en grados, p. ej. 715</translation>
    </message>
    <message>
        <source>Spin:</source>
        <translation>Girar:</translation>
    </message>
    <message>
        <source>It really turned:</source>
        <translation>Giró de verdad:</translation>
    </message>
    <message>
        <source>Mark the start heading: lay a strip of tape on the floor from the middle of the robot&apos;s front edge straight ahead, and put a piece of tape on the bumper above it. The robot spins whole turns counter-clockwise on the spot by its encoders and stops. Count the whole turns and read how far the bumper&apos;s mark is past the floor&apos;s: two turns that stop 5 degrees short are 715 degrees.</source>
        <translation>Marca el rumbo inicial: pega en el suelo una tira de cinta desde el centro del borde delantero del robot hacia delante, y un trozo de cinta en el parachoques encima de ella. El robot da vueltas completas en sentido antihorario sobre sí mismo según sus codificadores y se detiene. Cuenta las vueltas completas y mira cuánto ha pasado la marca del parachoques de la del suelo: dos vueltas que se quedan 5 grados cortas son 715 grados.</translation>
    </message>
    <message>
        <source>&amp;Apply and keep</source>
        <translation>&amp;Aplicar y guardar</translation>
    </message>
    <message>
        <source>&amp;Reset to the documented wheels</source>
        <translation>&amp;Restablecer las ruedas documentadas</translation>
    </message>
    <message>
        <source>Step 1 of 3: straight line</source>
        <translation>Paso 1 de 3: línea recta</translation>
    </message>
    <message>
        <source>Step 2 of 3: turn</source>
        <translation>Paso 2 de 3: giro</translation>
    </message>
    <message>
        <source>Step 3 of 3: result</source>
        <translation>Paso 3 de 3: resultado</translation>
    </message>
    <message>
        <source>Driving… Esc, Space or Stop stops it.</source>
        <translation>Avanzando… Esc, Espacio o Parar lo detienen.</translation>
    </message>
    <message>
        <source>Spinning… Esc, Space or Stop stops it.</source>
        <translation>Girando… Esc, Espacio o Parar lo detienen.</translation>
    </message>
    <message>
        <source>Driving… %1 of %2 mm by the encoders. Esc, Space or Stop stops it.</source>
        <translation>Avanzando… %1 de %2 mm según los codificadores. Esc, Espacio o Parar lo detienen.</translation>
    </message>
    <message>
        <source>Spinning… %1 of %2 degrees by the encoders. Esc, Space or Stop stops it.</source>
        <translation>Girando… %1 de %2 grados según los codificadores. Esc, Espacio o Parar lo detienen.</translation>
    </message>
    <message>
        <source>Stopped after %1 mm by the encoders. Now measure what it really drove.</source>
        <translation>Detenido tras %1 mm según los codificadores. Ahora mide cuánto avanzó de verdad.</translation>
    </message>
    <message>
        <source>Stopped after %1 mm by the encoders. This is a virtual robot: the measurements below come from its true position in the room, %2 mm from the start and %3 mm off the line.</source>
        <translation>Detenido tras %1 mm según los codificadores. Es un robot virtual: las medidas de abajo vienen de su posición real en la sala, a %2 mm del inicio y %3 mm fuera de la línea.</translation>
    </message>
    <message>
        <source>Stopped after %1 degrees by the encoders. Now read how far it really turned.</source>
        <translation>Detenido tras %1 grados según los codificadores. Ahora mira cuánto giró de verdad.</translation>
    </message>
    <message>
        <source>Stopped after %1 degrees by the encoders. This is a virtual robot: the angle below comes from its true heading in the room, %2 degrees.</source>
        <translation>Detenido tras %1 grados según los codificadores. Es un robot virtual: el ángulo de abajo viene de su rumbo real en la sala, %2 grados.</translation>
    </message>
    <message>
        <source>%1 Nothing was measured; run the step again.</source>
        <translation>%1 No se midió nada; repite el paso.</translation>
    </message>
    <message>
        <source>%1: “%2” is not a number. Type what you measured, in %3.</source>
        <translation>%1: «%2» no es un número. Escribe lo que mediste, en %3.</translation>
    </message>
    <message>
        <source>%1: %2 %3 cannot be. Type what you measured, more than 0 %3.</source>
        <translation>%1: %2 %3 no puede ser. Escribe lo que mediste, más de 0 %3.</translation>
    </message>
    <message>
        <source>%1: %2 %3 is more than 50 % off the %4 %3 the encoders counted. Measure again: a typing slip, or a wheel that slipped?</source>
        <translation>%1: %2 %3 se aleja más de un 50 % de los %4 %3 que contaron los codificadores. Vuelve a medir: ¿un error al escribir, o una rueda que patinó?</translation>
    </message>
    <message>
        <source>Drive the straight line, the turn or both first.</source>
        <translation>Haz primero la línea recta, el giro o ambos.</translation>
    </message>
    <message>
        <source>Measured distance</source>
        <translation>Distancia medida</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <source>Off the line: “%1” is not a distance in mm less than half the run; leave it empty if you did not measure it.</source>
        <translation>Fuera de la línea: «%1» no es una distancia en mm menor que la mitad de la marcha; déjalo vacío si no la mediste.</translation>
    </message>
    <message>
        <source>Straight line: the distance packet (19) says %1 mm, the encoders %2 mm%3.</source>
        <translation>Línea recta: el paquete de distancia (19) dice %1 mm, los codificadores %2 mm%3.</translation>
    </message>
    <message>
        <source>: they disagree</source>
        <translation>: no coinciden</translation>
    </message>
    <message>
        <source>Measured angle</source>
        <translation>Ángulo medido</translation>
    </message>
    <message>
        <source>degrees</source>
        <translation>grados</translation>
    </message>
    <message>
        <source>Turn: the angle packet (20) says %1 degrees, the encoders %2 degrees%3.</source>
        <translation>Giro: el paquete de ángulo (20) dice %1 grados, los codificadores %2 grados%3.</translation>
    </message>
    <message>
        <source>These runs cannot be right: %1</source>
        <translation>Estas marchas no pueden ser correctas: %1</translation>
    </message>
    <message>
        <source>This robot&apos;s firmware reports its own packets wrongly (Robot → Read firmware version… names it). The map uses the encoders.</source>
        <translation>El firmware de este robot informa mal sus propios paquetes (Robot → Leer la versión del firmware… lo nombra). El mapa usa los codificadores.</translation>
    </message>
    <message>
        <source>Firmware %1 reports its own packets wrongly. The map uses the encoders.</source>
        <translation>El firmware %1 informa mal sus propios paquetes. El mapa usa los codificadores.</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;Left wheel&lt;/b&gt; %1 mm (%2 × the documented 72 mm), &lt;b&gt;right wheel&lt;/b&gt; %3 mm (%4 ×)%5.&lt;br&gt;&lt;b&gt;Wheel base&lt;/b&gt; %6 mm (documented 235 mm).&lt;/p&gt;&lt;p&gt;A 1 m square driven by the encoders, predicted from these runs: &lt;b&gt;%7 mm&lt;/b&gt; from its start with the wheels counted now, &lt;b&gt;%8 mm&lt;/b&gt; with these.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Rueda izquierda&lt;/b&gt; %1 mm (%2 × los 72 mm documentados), &lt;b&gt;rueda derecha&lt;/b&gt; %3 mm (%4 ×)%5.&lt;br&gt;&lt;b&gt;Distancia entre ruedas&lt;/b&gt; %6 mm (documentada 235 mm).&lt;/p&gt;&lt;p&gt;Un cuadrado de 1 m recorrido según los codificadores, previsto a partir de estas marchas: &lt;b&gt;%7 mm&lt;/b&gt; de su inicio con las ruedas contadas ahora, &lt;b&gt;%8 mm&lt;/b&gt; con estas.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>: the two wheels differ</source>
        <translation>: las dos ruedas son distintas</translation>
    </message>
    <message>
        <source>%1 is counted with the documented wheels: 72 mm, 235 mm apart.</source>
        <translation>%1 se cuenta con las ruedas documentadas: 72 mm, a 235 mm una de otra.</translation>
    </message>
    <message>
        <source>%1 is counted with wheels of %2 mm (left) and %3 mm (right), %4 mm apart, measured on %5.</source>
        <translation>%1 se cuenta con ruedas de %2 mm (izquierda) y %3 mm (derecha), a %4 mm una de otra, medidas el %5.</translation>
    </message>
</context>
<context>
    <name>CalibrationWizardAction</name>
    <message>
        <source>&amp;Calibrate odometry…</source>
        <translation>&amp;Calibrar la odometría…</translation>
    </message>
    <message>
        <source>Measure the selected robot&apos;s real wheels, so that its map stops drifting</source>
        <translation>Medir las ruedas reales del robot seleccionado, para que su mapa deje de desviarse</translation>
    </message>
</context>
<context>
    <name>ChannelChooser</name>
    <message>
        <source>Bumps &amp; cliffs</source>
        <translation>Choques y desniveles</translation>
    </message>
    <message>
        <source>Battery</source>
        <translation>Batería</translation>
    </message>
    <message>
        <source>Motion</source>
        <translation>Movimiento</translation>
    </message>
    <message>
        <source>Light bumpers</source>
        <translation>Parachoques de luz</translation>
    </message>
    <message>
        <source>Motors &amp; dirt</source>
        <translation>Motores y suciedad</translation>
    </message>
    <message>
        <source>Cargo bay</source>
        <translation>Bahía de carga</translation>
    </message>
    <message>
        <source>IR, buttons &amp; mode</source>
        <translation>IR, botones y modo</translation>
    </message>
    <message>
        <source>Unused</source>
        <translation>Sin uso</translation>
    </message>
    <message>
        <source>Choose channels</source>
        <translation>Elegir canales</translation>
    </message>
    <message>
        <source>Choose the sensor packets this plot shows</source>
        <translation>Elige los paquetes de sensores que muestra esta gráfica</translation>
    </message>
    <message numerus="yes">
        <source>Channels (%n)</source>
        <translation>
            <numerusform>Canales (%n)</numerusform>
            <numerusform>Canales (%n)</numerusform>
        </translation>
    </message>
    <message>
        <source>plain numbers</source>
        <translation>números sin unidad</translation>
    </message>
    <message>
        <source>This plot&apos;s axes show %1 and %2: add a plot for %3</source>
        <translation>Los ejes de este gráfico muestran %1 y %2: añada un gráfico para %3</translation>
    </message>
</context>
<context>
    <name>CommandDecoder</name>
    <message>
        <source> (straight)</source>
        <translation> (recto)</translation>
    </message>
    <message>
        <source> (turn in place clockwise)</source>
        <translation> (giro sobre sí mismo en sentido horario)</translation>
    </message>
    <message>
        <source> (turn in place counter-clockwise)</source>
        <translation> (giro sobre sí mismo en sentido antihorario)</translation>
    </message>
    <message>
        <source>group %1 (packets %2..%3)</source>
        <translation>grupo %1 (paquetes %2..%3)</translation>
    </message>
    <message>
        <source>packet %1 (not on the %2)</source>
        <translation>paquete %1 (no existe en el %2)</translation>
    </message>
    <message>
        <source>not a command of the %1</source>
        <translation>no es un comando del %1</translation>
    </message>
    <message>
        <source>%1, incomplete: its count byte is missing</source>
        <translation>%1, incompleto: falta su byte de recuento</translation>
    </message>
    <message>
        <source>%1, incomplete: %2 of %3 data bytes</source>
        <translation>%1, incompleto: %2 de %3 bytes de datos</translation>
    </message>
    <message>
        <source>rest</source>
        <translation>silencio</translation>
    </message>
    <message>
        <source>%1 slot %2, %3%4</source>
        <translation>%1 ranura %2, %3%4</translation>
    </message>
    <message numerus="yes">
        <source>%n byte</source>
        <translation>
            <numerusform>%n byte</numerusform>
            <numerusform>%n bytes</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n bytes</source>
        <translation>
            <numerusform>%n byte</numerusform>
            <numerusform>%n bytes</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 code %2%3</source>
        <translation>%1 código %2%3</translation>
    </message>
    <message>
        <source>%1 velocity %2 radius %3%4</source>
        <translation>%1 velocidad %2 radio %3%4</translation>
    </message>
    <message>
        <source>pause</source>
        <translation>pausa</translation>
    </message>
    <message>
        <source>resume</source>
        <translation>reanudar</translation>
    </message>
    <message>
        <source>state %1</source>
        <translation>estado %1</translation>
    </message>
    <message>
        <source>%1 off</source>
        <translation>%1 desactivado</translation>
    </message>
    <message>
        <source>Type the bytes to send, for example 128 131 or 0x80 0x83.</source>
        <translation>Escriba los bytes que desea enviar, por ejemplo 128 131 o 0x80 0x83.</translation>
    </message>
    <message>
        <source>Byte %1: “%2” is not a number.</source>
        <translation>Byte %1: «%2» no es un número.</translation>
    </message>
    <message>
        <source>Byte %1: %2 is outside 0..255.</source>
        <translation>Byte %1: %2 está fuera de 0..255.</translation>
    </message>
    <message>
        <source>Byte %1: %2 is not an opcode of the %3.</source>
        <translation>Byte %1: %2 no es un código de operación del %3.</translation>
    </message>
    <message>
        <source>%1 needs its song number and length bytes.</source>
        <translation>%1 necesita sus bytes de número de canción y longitud.</translation>
    </message>
    <message>
        <source>%1 needs its count byte.</source>
        <translation>%1 necesita su byte de recuento.</translation>
    </message>
    <message>
        <source>%1 takes %2 data bytes; got %3.</source>
        <translation>%1 lleva %2 bytes de datos; se recibieron %3.</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message numerus="yes">
        <source>%n note</source>
        <translation>
            <numerusform>%n nota</numerusform>
            <numerusform>%n notas</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n notes</source>
        <translation>
            <numerusform>%n nota</numerusform>
            <numerusform>%n notas</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n packet</source>
        <translation>
            <numerusform>%n paquete</numerusform>
            <numerusform>%n paquetes</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n packets</source>
        <translation>
            <numerusform>%n paquete</numerusform>
            <numerusform>%n paquetes</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ComparisonBar</name>
    <message>
        <source>Compared with %1</source>
        <translation>Comparado con %1</translation>
    </message>
    <message>
        <source>aligned at the start</source>
        <translation>alineado al inicio</translation>
    </message>
    <message>
        <source>aligned at “%1”</source>
        <translation>alineado en «%1»</translation>
    </message>
    <message>
        <source>Where the two runs line up in time: their starts, or a marker both hold</source>
        <translation>Dónde coinciden en el tiempo los dos recorridos: en sus inicios o en una marca que tengan ambos</translation>
    </message>
    <message>
        <source>Close comparison</source>
        <translation>Cerrar comparación</translation>
    </message>
</context>
<context>
    <name>ConnectionBar</name>
    <message>
        <source>Virtual robot</source>
        <translation>Robot virtual</translation>
    </message>
    <message>
        <source>Serial port</source>
        <translation>Puerto serie</translation>
    </message>
    <message>
        <source>TCP (ser2net)</source>
        <translation>TCP (ser2net)</translation>
    </message>
    <message>
        <source>Transport</source>
        <translation>Transporte</translation>
    </message>
    <message>
        <source>/dev/ttyUSB0 or a typed path</source>
        <translation>/dev/ttyUSB0 o una ruta escrita</translation>
    </message>
    <message>
        <source>List the serial ports again</source>
        <translation>Volver a listar los puertos serie</translation>
    </message>
    <message>
        <source>host:port, e.g. raspberrypi:3333</source>
        <translation>host:puerto, p. ej. raspberrypi:3333</translation>
    </message>
    <message>
        <source>TCP bridge</source>
        <translation>Puente TCP</translation>
    </message>
    <message>
        <source>Auto</source>
        <translation>Auto</translation>
    </message>
    <message>
        <source>Robot profile</source>
        <translation>Perfil del robot</translation>
    </message>
    <message>
        <source>Default baud</source>
        <translation>Baudios por defecto</translation>
    </message>
    <message>
        <source>Baud rate</source>
        <translation>Velocidad en baudios</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Conectar</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>Desconectar</translation>
    </message>
    <message>
        <source>Choose a serial port or type its path.</source>
        <translation>Elija un puerto serie o escriba su ruta.</translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation>Actualizar</translation>
    </message>
    <message>
        <source>Disconnect to change the port</source>
        <translation>Desconecte para cambiar el puerto</translation>
    </message>
    <message>
        <source>Wake line</source>
        <translation>Línea de despertar</translation>
    </message>
    <message>
        <source>Wake: RTS</source>
        <translation>Despertar: RTS</translation>
    </message>
    <message>
        <source>Wake: DTR</source>
        <translation>Despertar: DTR</translation>
    </message>
    <message>
        <source>Wake: both</source>
        <translation>Despertar: ambas</translation>
    </message>
    <message>
        <source>Wake: none</source>
        <translation>Despertar: ninguna</translation>
    </message>
    <message>
        <source>The adapter&apos;s line wired to the robot&apos;s BRC pin, pulsed to wake it and keep it awake. Many cables use RTS, some DTR; both pulses the two; none: the cable has no BRC wire.</source>
        <translation>La línea del adaptador conectada al pin BRC del robot, que se pulsa para despertarlo y mantenerlo despierto. Muchos cables usan RTS, algunos DTR; ambas pulsa las dos; ninguna: el cable no tiene hilo BRC.</translation>
    </message>
    <message>
        <source>Wake</source>
        <translation>Despertar</translation>
    </message>
    <message>
        <source>Pulse the robot&apos;s BRC pin: switches on a robot switched off at its power button</source>
        <translation>Envía un pulso al pin BRC del robot: enciende un robot apagado con su botón de encendido</translation>
    </message>
</context>
<context>
    <name>ConnectionCheckup</name>
    <message>
        <source>Which robot is this?</source>
        <translation>¿Qué robot es este?</translation>
    </message>
    <message>
        <source>Roomba 500</source>
        <translation>Roomba 500</translation>
    </message>
    <message>
        <source>%1 on %2</source>
        <translation>%1 en %2</translation>
    </message>
    <message>
        <source>%1 is a Roomba 500 or a Create 2, and the two answer every question alike.

The Roomba 500 is the cleaning robot of the 500 series. The Create 2 is iRobot&apos;s educational robot, built on the Roomba 600 (a Roomba 600 counts as a Create 2).

The choice decides how the wheel counts are read: the wrong one mirrors every turn on the map. Until you choose, the map draws no path for this robot. The answer is kept for this robot; the profile in the connection bar changes it later.</source>
        <translation>%1 es un Roomba 500 o un Create 2, y los dos responden igual a cada pregunta.

El Roomba 500 es el robot aspirador de la serie 500. El Create 2 es el robot educativo de iRobot, construido sobre el Roomba 600 (un Roomba 600 cuenta como Create 2).

La elección decide cómo se leen los contadores de las ruedas: la equivocada refleja cada giro en el mapa. Hasta que elija, el mapa no dibuja ningún recorrido para este robot. La respuesta se guarda para este robot; el perfil de la barra de conexión la cambia más tarde.</translation>
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
        <translation>Este ordenador no tiene ningún puerto serie: conecte el cable del robot y elija luego su puerto en la barra de conexión.</translation>
    </message>
    <message>
        <source>%1 does not exist. The serial ports on this computer: %2. Choose one in the connection bar.</source>
        <translation>%1 no existe. Los puertos serie de este ordenador: %2. Elija uno en la barra de conexión.</translation>
    </message>
    <message>
        <source>This user may not open %1: add yourself to the group %2 (sudo adduser $USER %2), then log out and in again.</source>
        <translation>Este usuario no puede abrir %1: añádase al grupo %2 (sudo adduser $USER %2) y luego cierre la sesión y vuelva a entrar.</translation>
    </message>
    <message>
        <source>Check that the bridge at %1:%2 is on and on this network, and that ser2net (or the Wi-Fi serial module) listens on that port.</source>
        <translation>Compruebe que el puente en %1:%2 está encendido y en esta red, y que ser2net (o el módulo serie wifi) escucha en ese puerto.</translation>
    </message>
    <message>
        <source>Over raw TCP the bridge&apos;s serial rate is fixed in its own settings: it must be the robot&apos;s rate (115200 for a Roomba 500 or Create 2, 57600 for a Create).</source>
        <translation>Por TCP sin más, la velocidad serie del puente se fija en su propia configuración: debe ser la del robot (115200 para un Roomba 500 o Create 2, 57600 para un Create).</translation>
    </message>
    <message>
        <source>Bytes come back but make no sense at any rate: check that the cable is a robot&apos;s serial cable (5 V TTL, not RS-232) and that nothing else uses the port.</source>
        <translation>Vuelven bytes que no tienen sentido a ninguna velocidad: compruebe que el cable es un cable serie de robot (TTL de 5 V, no RS-232) y que nada más usa el puerto.</translation>
    </message>
    <message>
        <source>Check that the robot is switched on (its power light is lit) and that its cable is firmly in; a robot asleep on its dock wakes when it is taken off.</source>
        <translation>Compruebe que el robot está encendido (su luz de encendido brilla) y que su cable está bien puesto; un robot dormido en su base despierta al sacarlo de ella.</translation>
    </message>
    <message>
        <source>Then press Connect to try again.</source>
        <translation>Después pulse Conectar para volver a intentarlo.</translation>
    </message>
    <message>
        <source>No port is chosen. The serial ports on this computer: %1. Choose one in the connection bar.</source>
        <translation>No hay ningún puerto elegido. Los puertos serie de este ordenador: %1. Elija uno en la barra de conexión.</translation>
    </message>
</context>
<context>
    <name>DashboardCommandLine</name>
    <message>
        <source>%1 needs a value; see --help</source>
        <translation>%1 necesita un valor; consulte --help</translation>
    </message>
    <message>
        <source>choose one of --sim, --port, --tcp and --replay</source>
        <translation>elija solo una de --sim, --port, --tcp y --replay</translation>
    </message>
    <message>
        <source>--record: the folder of &apos;%1&apos; does not exist</source>
        <translation>--record: la carpeta de &apos;%1&apos; no existe</translation>
    </message>
    <message>
        <source>unknown language &apos;%1&apos; (%2)</source>
        <translation>idioma desconocido &apos;%1&apos; (%2)</translation>
    </message>
    <message>
        <source>unknown argument &apos;%1&apos;; see --help</source>
        <translation>argumento desconocido &apos;%1&apos;; consulte --help</translation>
    </message>
    <message>
        <source>--replay reads the profile and baud from the recording; leave out --profile, --baud and --brc-line</source>
        <translation>--replay lee el perfil y los baudios de la grabación; omita --profile, --baud y --brc-line</translation>
    </message>
    <message>
        <source>--record records a robot; a replay is already a recording</source>
        <translation>--record graba un robot; una reproducción ya es una grabación</translation>
    </message>
    <message>
        <source>cannot replay %1</source>
        <translation>no se puede reproducir %1</translation>
    </message>
    <message>
        <source>--sim takes 1 to %1 robots, not %2</source>
        <translation>--sim admite de 1 a %1 robots, no %2</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a size in mm within half of the documents&apos; %3 mm</source>
        <translation>%1: «%2» no es un tamaño en mm dentro de la mitad de los %3 mm documentados</translation>
    </message>
    <message>
        <source>--wheel-diameter, --left-wheel-diameter, --right-wheel-diameter and --wheel-base go with --sim</source>
        <translation>--wheel-diameter, --left-wheel-diameter, --right-wheel-diameter y --wheel-base van con --sim</translation>
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
        <translation>Uso: roomba-dashboard [--sim [N] | --port RUTA | --tcp HOST:PUERTO | --replay ARCHIVO]
                      [--profile P] [--baud N] [--brc-line LÍNEA] [--record ARCHIVO]
                      [--lang CÓDIGO]
                      [--foxglove [[DIRECCIÓN:]PUERTO]]

  --sim [N]          el robot virtual integrado, o N de ellos (hasta %2) en una sala
  --port RUTA        un puerto serie, adaptador USB o pseudoterminal
  --tcp HOST:PUERTO  un puente serie sobre TCP como ser2net
  --replay ARCHIVO   reproduce una grabación (.oirec) como si fuera el robot
  --profile P        roomba500, create2 (también roomba600), create1 (también create) o auto
  --baud N           la velocidad de la línea; si se omite, la del perfil
  --brc-line LÍNEA   la línea de despertar: la línea del adaptador unida al pin BRC del
                     robot, pulsada para despertarlo y mantenerlo despierto: rts (por
                     defecto), dtr, both o none (el cable no tiene hilo BRC: no se pulsa)
  --record ARCHIVO   graba en ARCHIVO cada byte enviado al robot y recibido de él
  --lang CÓDIGO      el idioma de la ventana: %1
  --foxglove [[DIRECCIÓN:]PUERTO]  servir los robots en vivo a Foxglove, Lichtblick y
                     PlotJuggler (protocolo Foxglove WebSocket) en DIRECCIÓN (por omisión
                     127.0.0.1, solo este equipo) y PUERTO (por omisión 8765)
  --wheel-diameter MM, --left-wheel-diameter MM, --right-wheel-diameter MM,
  --wheel-base MM    con --sim: las ruedas reales del robot virtual (documentos:
                     72 y 235 mm), para que su odometría se desvíe como la de uno
                     real, y practicar Robot &gt; Calibrar la odometría
  --help, --version

Sin opción de conexión, el panel vuelve a conectar los robots que tenía,
o en el primer inicio el robot virtual; con una, tiene solo ese robot (o esos
robots virtuales) y guarda la lista para la próxima vez. Mayús+Esc detiene
todos los robots. Sin --lang usa el idioma elegido en su menú Ver, o el del
sistema.
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
  --battery-fade PORC[,PORC...], --battery-resistance MOHM[,MOHM...]
                     con --sim: baterías envejecidas, una cifra por robot (la última
                     para el resto): la parte perdida de sus 3000 mAh (0 a 90) y su
                     resistencia interna (50 a 5000 mΩ; una batería nueva, 250)
</translation>
    </message>
    <message>
        <source>--battery-fade: &apos;%1&apos; is not a share from 0 to 90 %</source>
        <translation>--battery-fade: &apos;%1&apos; no es una proporción de 0 a 90 %</translation>
    </message>
    <message>
        <source>--battery-resistance: &apos;%1&apos; is not a resistance from 50 to 5000 mΩ</source>
        <translation>--battery-resistance: &apos;%1&apos; no es una resistencia de 50 a 5000 mΩ</translation>
    </message>
    <message>
        <source>--battery-fade and --battery-resistance go with --sim</source>
        <translation>--battery-fade y --battery-resistance van con --sim</translation>
    </message>
</context>
<context>
    <name>Demos</name>
    <message>
        <source>Abort demo</source>
        <translation>Cancelar demo</translation>
    </message>
    <message>
        <source>Cover</source>
        <translation>Cubrir</translation>
    </message>
    <message>
        <source>Cover and Dock</source>
        <translation>Cubrir y volver a la base</translation>
    </message>
    <message>
        <source>Spot Cover</source>
        <translation>Cubrir zona</translation>
    </message>
    <message>
        <source>Mouse</source>
        <translation>Ratón</translation>
    </message>
    <message>
        <source>Drive Figure Eight</source>
        <translation>Conducir en ocho</translation>
    </message>
    <message>
        <source>Wimp</source>
        <translation>Miedica</translation>
    </message>
    <message>
        <source>Home</source>
        <translation>Casa</translation>
    </message>
    <message>
        <source>Tag</source>
        <translation>Pilla-pilla</translation>
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
        <translation>&amp;Restablecer disposición</translation>
    </message>
    <message>
        <source>&amp;Next pane</source>
        <translation>Panel &amp;siguiente</translation>
    </message>
    <message>
        <source>&amp;Previous pane</source>
        <translation>Panel an&amp;terior</translation>
    </message>
</context>
<context>
    <name>DoctorDetails</name>
    <message>
        <source>Details…</source>
        <translation>Detalles…</translation>
    </message>
    <message>
        <source>Connection check details</source>
        <translation>Detalles de la comprobación de la conexión</translation>
    </message>
    <message>
        <source>Checking the connection…</source>
        <translation>Comprobando la conexión…</translation>
    </message>
    <message>
        <source>Connection check</source>
        <translation>Comprobación de la conexión</translation>
    </message>
    <message>
        <source>What was tried</source>
        <translation>Lo que se probó</translation>
    </message>
    <message>
        <source>What was tried:</source>
        <translation>Lo que se probó:</translation>
    </message>
    <message>
        <source>What to do next:</source>
        <translation>Qué hacer ahora:</translation>
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
        <translation>Drive (137): velocidad y radio</translation>
    </message>
    <message>
        <source>Drive Direct (145): each wheel</source>
        <translation>Drive Direct (145): cada rueda</translation>
    </message>
    <message>
        <source>Drive PWM (146): each wheel, raw power</source>
        <translation>Drive PWM (146): cada rueda, potencia directa</translation>
    </message>
    <message>
        <source>Speed limit</source>
        <translation>Límite de velocidad</translation>
    </message>
    <message>
        <source>Passive mode: enter Safe to drive</source>
        <translation>Modo Passive: pase a Safe para conducir</translation>
    </message>
    <message>
        <source>Enter Safe</source>
        <translation>Pasar a Safe</translation>
    </message>
    <message>
        <source>Drive pad</source>
        <translation>Panel de conducción</translation>
    </message>
    <message>
        <source>Drive Direct (145) is not available on the %1</source>
        <translation>Drive Direct (145) no está disponible en el %1</translation>
    </message>
    <message>
        <source>Drive PWM (146) is not available on the %1</source>
        <translation>Drive PWM (146) no está disponible en el %1</translation>
    </message>
    <message>
        <source>Drive (137) is not available on the %1</source>
        <translation>Drive (137) no está disponible en el %1</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Detenido</translation>
    </message>
    <message>
        <source>Drive Direct: right %1, left %2 mm/s</source>
        <translation>Drive Direct: derecha %1, izquierda %2 mm/s</translation>
    </message>
    <message>
        <source>Drive PWM: right %1, left %2</source>
        <translation>Drive PWM: derecha %1, izquierda %2</translation>
    </message>
    <message>
        <source>straight</source>
        <translation>recto</translation>
    </message>
    <message>
        <source>turn in place, clockwise</source>
        <translation>giro sobre sí mismo, sentido horario</translation>
    </message>
    <message>
        <source>turn in place, anticlockwise</source>
        <translation>giro sobre sí mismo, sentido antihorario</translation>
    </message>
    <message>
        <source>radius %1 mm</source>
        <translation>radio %1 mm</translation>
    </message>
    <message>
        <source>Drive %1 mm/s, %2</source>
        <translation>Conducir a %1 mm/s, %2</translation>
    </message>
    <message>
        <source>Right wheel %1 mm/s, left wheel %2 mm/s</source>
        <translation>Rueda derecha %1 mm/s, rueda izquierda %2 mm/s</translation>
    </message>
    <message>
        <source>Right wheel power %1, left wheel power %2</source>
        <translation>Potencia rueda derecha %1, rueda izquierda %2</translation>
    </message>
    <message>
        <source>Turning in place clockwise, %1 mm/s</source>
        <translation>Girando sobre sí mismo en sentido horario, %1 mm/s</translation>
    </message>
    <message>
        <source>Turning in place anticlockwise, %1 mm/s</source>
        <translation>Girando sobre sí mismo en sentido antihorario, %1 mm/s</translation>
    </message>
    <message>
        <source>Forward %1 mm/s</source>
        <translation>Adelante %1 mm/s</translation>
    </message>
    <message>
        <source>Backward %1 mm/s</source>
        <translation>Atrás %1 mm/s</translation>
    </message>
    <message>
        <source>%1, straight</source>
        <translation>%1, recto</translation>
    </message>
    <message>
        <source>%1, turning left (radius %2 mm)</source>
        <translation>%1, girando a la izquierda (radio %2 mm)</translation>
    </message>
    <message>
        <source>%1, turning right (radius %2 mm)</source>
        <translation>%1, girando a la derecha (radio %2 mm)</translation>
    </message>
</context>
<context>
    <name>FirmwareCorrections</name>
    <message>
        <source>This robot&apos;s firmware (before 3.3.0) reports the distance wrongly: do not trust it. The map uses the wheel encoders instead.</source>
        <translation>El firmware de este robot (anterior a 3.3.0) informa mal de la distancia: no se fíe de ella. El mapa usa en su lugar los codificadores de las ruedas.</translation>
    </message>
    <message>
        <source>This robot&apos;s firmware (before 3.3.0) reports the requested radius wrongly: do not trust it.</source>
        <translation>El firmware de este robot (anterior a 3.3.0) informa mal del radio pedido: no se fíe de él.</translation>
    </message>
</context>
<context>
    <name>FirmwareReading</name>
    <message>
        <source>Read firmware version</source>
        <translation>Leer la versión del firmware</translation>
    </message>
    <message>
        <source>Read &amp;firmware version…</source>
        <translation>Leer la versión del &amp;firmware…</translation>
    </message>
    <message>
        <source>Reset the selected robot to read its firmware version, and so what it reports wrongly</source>
        <translation>Reiniciar el robot seleccionado para leer la versión de su firmware y, con ella, qué datos da mal</translation>
    </message>
    <message>
        <source>The firmware version is printed only when the robot starts up, so %1 will be reset (Reset, opcode 7): it stops, leaves its mode and reboots as if its battery had been taken out. Enter Safe again afterwards if you were driving it.

Reset %1 now?</source>
        <translation>La versión del firmware solo se imprime al arrancar el robot, así que %1 se reiniciará (Reset, código 7): se detiene, sale de su modo y arranca de nuevo como si se le hubiera quitado la batería. Después vuelva a pasar a Safe si lo estaba conduciendo.

¿Reiniciar %1 ahora?</translation>
    </message>
    <message>
        <source>%1 runs %2 (version %3).

%4

It printed: %5</source>
        <translation>%1 usa %2 (versión %3).

%4

Imprimió: %5</translation>
    </message>
    <message>
        <source>Firmware version</source>
        <translation>Versión del firmware</translation>
    </message>
</context>
<context>
    <name>FleetConsole</name>
    <message>
        <source>%1 · robots: %2 · speaking as %3</source>
        <translation>%1 · robots: %2 · habla como %3</translation>
    </message>
    <message>
        <source>%1 · connecting…</source>
        <translation>%1 · conectando…</translation>
    </message>
    <message>
        <source>%1 · not connected: %2</source>
        <translation>%1 · sin conexión: %2</translation>
    </message>
    <message>
        <source>this window</source>
        <translation>esta ventana</translation>
    </message>
    <message>
        <source>Stopped the robot at %1</source>
        <translation>Robot detenido a las %1</translation>
    </message>
    <message>
        <source>Stopped all %1 robots at %2</source>
        <translation>Detenidos los %1 robots a las %2</translation>
    </message>
    <message>
        <source>%1 · connection lost at %2, trying again…</source>
        <translation>%1 · conexión perdida a las %2, reintentando…</translation>
    </message>
</context>
<context>
    <name>FleetDirectory</name>
    <message>
        <source>%1: %2 is not JSON: %3</source>
        <translation>%1: %2 no es JSON: %3</translation>
    </message>
    <message>
        <source>%1: %2 is not a JSON object</source>
        <translation>%1: %2 no es un objeto JSON</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1: telemetry: %2</source>
        <translation>%1: telemetría: %2</translation>
    </message>
    <message>
        <source>%1: stats: %2</source>
        <translation>%1: estadísticas: %2</translation>
    </message>
</context>
<context>
    <name>FleetTile</name>
    <message>
        <source>ONLINE</source>
        <translation>EN LÍNEA</translation>
    </message>
    <message>
        <source>OFFLINE</source>
        <translation>SIN CONEXIÓN</translation>
    </message>
    <message>
        <source>mode not known</source>
        <translation>modo desconocido</translation>
    </message>
    <message>
        <source>BUMP both</source>
        <translation>CHOQUE ambos</translation>
    </message>
    <message>
        <source>BUMP left</source>
        <translation>CHOQUE izquierda</translation>
    </message>
    <message>
        <source>BUMP right</source>
        <translation>CHOQUE derecha</translation>
    </message>
    <message>
        <source>CLIFF ×%1</source>
        <translation>PRECIPICIO ×%1</translation>
    </message>
    <message>
        <source>WHEEL DROP</source>
        <translation>RUEDA CAÍDA</translation>
    </message>
    <message>
        <source>no bump, no cliff</source>
        <translation>sin choque, sin precipicio</translation>
    </message>
    <message>
        <source>link not known</source>
        <translation>enlace desconocido</translation>
    </message>
    <message>
        <source>link %1</source>
        <translation>enlace %1</translation>
    </message>
    <message>
        <source>%1 · %2/s</source>
        <translation>%1 · %2/s</translation>
    </message>
    <message>
        <source>nobody in control</source>
        <translation>nadie lo controla</translation>
    </message>
    <message>
        <source>driven by %1</source>
        <translation>conducido por %1</translation>
    </message>
    <message>
        <source>Robot %1, %2</source>
        <translation>Robot %1, %2</translation>
    </message>
    <message>
        <source>%1
Click to select this robot: every dock shows it</source>
        <translation>%1
Haga clic para seleccionar este robot: todos los paneles lo muestran</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>NO BROKER</source>
        <translation>SIN BRÓKER</translation>
    </message>
    <message>
        <source>battery %1 %</source>
        <translation>batería %1 %</translation>
    </message>
    <message>
        <source>%1 · %2</source>
        <translation>%1 · %2</translation>
    </message>
    <message>
        <source>broker unreachable</source>
        <translation>bróker inalcanzable</translation>
    </message>
    <message>
        <source>%1&apos;s program %2</source>
        <translation>programa %2 de %1</translation>
    </message>
    <message>
        <source>MAY STILL BE MOVING</source>
        <translation>QUIZÁ AÚN SE MUEVE</translation>
    </message>
    <message>
        <source>pack %1, %2 mAh</source>
        <translation>batería: %1, %2 mAh</translation>
    </message>
    <message>
        <source>pack %1</source>
        <translation>batería: %1</translation>
    </message>
    <message>
        <source>%1 % · %2</source>
        <translation>%1 % · %2</translation>
    </message>
    <message>
        <source>pick it up, switch it off</source>
        <translation>levántelo y apáguelo</translation>
    </message>
    <message>
        <source>bridge offline since %1</source>
        <translation>puente caído desde las %1</translation>
    </message>
    <message>
        <source>bridge offline</source>
        <translation>puente caído</translation>
    </message>
    <message>
        <source>robot not answering</source>
        <translation>robot sin respuesta</translation>
    </message>
    <message>
        <source>robot silent (link stale)</source>
        <translation>robot mudo (enlace obsoleto)</translation>
    </message>
    <message>
        <source>%1 cut off</source>
        <translation>se cortó a %1</translation>
    </message>
    <message>
        <source>%1&apos;s program cut off</source>
        <translation>se cortó el programa de %1</translation>
    </message>
    <message>
        <source>, cutting off %1</source>
        <translation>, lo que cortó a %1</translation>
    </message>
    <message>
        <source>, cutting off %1&apos;s program %2</source>
        <translation>, lo que cortó el programa %2 de %1</translation>
    </message>
    <message>
        <source>%1&apos;s bridge went offline at %2 while the robot was driving%3. A real robot keeps its last drive when its bridge dies: pick it up and hold its power button to switch it off, then restart the bridge on the computer beside it.</source>
        <translation>El puente de %1 se cayó a las %2 mientras el robot conducía%3. Un robot real mantiene su última orden de marcha cuando su puente falla: levántelo y mantenga pulsado su botón de encendido para apagarlo, y luego reinicie el puente en el equipo que tiene al lado.</translation>
    </message>
    <message>
        <source>%1&apos;s bridge went offline at %2%3 (the broker is fine): check the bridge on the computer beside the robot, and restart it.</source>
        <translation>El puente de %1 se cayó a las %2%3 (el bróker funciona): compruebe el puente en el equipo que hay junto al robot y reinícielo.</translation>
    </message>
    <message>
        <source>%1
%2
Click to select this robot: every dock shows it</source>
        <translation>%1
%2
Haga clic para seleccionar este robot: todos los paneles lo muestran</translation>
    </message>
</context>
<context>
    <name>FleetView</name>
    <message>
        <source>Fleet view</source>
        <translation>Vista de la flota</translation>
    </message>
    <message>
        <source>Connect to broker…</source>
        <translation>Conectar con el bróker…</translation>
    </message>
    <message>
        <source>Not connected to a broker</source>
        <translation>Sin conexión con un bróker</translation>
    </message>
    <message>
        <source>Connect to a broker to see every robot whose bridge publishes there.</source>
        <translation>Conéctese a un bróker para ver cada robot cuyo puente publica allí.</translation>
    </message>
    <message>
        <source>No robot on this broker yet. Each appears as its bridge starts.</source>
        <translation>Aún no hay robots en este bróker. Cada uno aparece cuando arranca su puente.</translation>
    </message>
    <message>
        <source>Reconnect…</source>
        <translation>Reconectar…</translation>
    </message>
    <message>
        <source>Another broker…</source>
        <translation>Otro bróker…</translation>
    </message>
    <message>
        <source>By name</source>
        <translation>Por nombre</translation>
    </message>
    <message>
        <source>By pack health</source>
        <translation>Por estado de la batería</translation>
    </message>
    <message>
        <source>The order of the tiles: by name, or by the health of each robot&apos;s battery pack, the one to replace first.</source>
        <translation>El orden de las fichas: por nombre o por el estado de la batería de cada robot, primero la que antes hay que cambiar.</translation>
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
        <translation>Pulsar stick izquierdo</translation>
    </message>
    <message>
        <source>Right stick press</source>
        <translation>Pulsar stick derecho</translation>
    </message>
    <message>
        <source>D-pad up</source>
        <translation>Cruceta arriba</translation>
    </message>
    <message>
        <source>D-pad down</source>
        <translation>Cruceta abajo</translation>
    </message>
    <message>
        <source>D-pad left</source>
        <translation>Cruceta izquierda</translation>
    </message>
    <message>
        <source>D-pad right</source>
        <translation>Cruceta derecha</translation>
    </message>
    <message>
        <source>none</source>
        <translation>ninguno</translation>
    </message>
    <message>
        <source>button %1</source>
        <translation>botón %1</translation>
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
        <translation>comando %1</translation>
    </message>
    <message>
        <source>Gamepad</source>
        <translation>Mando</translation>
    </message>
</context>
<context>
    <name>GamepadPanel</name>
    <message>
        <source>Would send:</source>
        <translation>Enviaría:</translation>
    </message>
    <message>
        <source>Left stick</source>
        <translation>Stick izquierdo</translation>
    </message>
    <message>
        <source>Drive Direct: right %1 mm/s, left %2 mm/s</source>
        <translation>Drive Direct: derecha %1 mm/s, izquierda %2 mm/s</translation>
    </message>
    <message>
        <source>Drive PWM: right %1, left %2</source>
        <translation>Drive PWM: derecha %1, izquierda %2</translation>
    </message>
    <message>
        <source>Stop: Drive 0 mm/s</source>
        <translation>Parar: Drive 0 mm/s</translation>
    </message>
    <message>
        <source>Forward: Drive %1 mm/s, straight</source>
        <translation>Adelante: Drive %1 mm/s, recto</translation>
    </message>
    <message>
        <source>Reverse: Drive %1 mm/s, straight</source>
        <translation>Atrás: Drive %1 mm/s, recto</translation>
    </message>
    <message>
        <source>Spin clockwise: Drive %1 mm/s, radius -1</source>
        <translation>Girar en sentido horario: Drive %1 mm/s, radio -1</translation>
    </message>
    <message>
        <source>Spin counter-clockwise: Drive %1 mm/s, radius 1</source>
        <translation>Girar en sentido antihorario: Drive %1 mm/s, radio 1</translation>
    </message>
    <message>
        <source>Forward, arcing right</source>
        <translation>Adelante, en curva a la derecha</translation>
    </message>
    <message>
        <source>Forward, arcing left</source>
        <translation>Adelante, en curva a la izquierda</translation>
    </message>
    <message>
        <source>Reverse, arcing right</source>
        <translation>Atrás, en curva a la derecha</translation>
    </message>
    <message>
        <source>Reverse, arcing left</source>
        <translation>Atrás, en curva a la izquierda</translation>
    </message>
    <message>
        <source>%1: Drive %2 mm/s, radius %3 mm</source>
        <translation>%1: Drive %2 mm/s, radio %3 mm</translation>
    </message>
    <message>
        <source>Gamepads unavailable: %1</source>
        <translation>Mandos no disponibles: %1</translation>
    </message>
    <message>
        <source>No gamepad connected — plug one in to drive with it</source>
        <translation>No hay ningún mando conectado: conecte uno para conducir con él</translation>
    </message>
    <message>
        <source>Dead-man (%1) held: driving</source>
        <translation>Botón de hombre muerto (%1) pulsado: conduciendo</translation>
    </message>
    <message>
        <source>Dead-man (%1) released: hold it to drive</source>
        <translation>Botón de hombre muerto (%1) suelto: manténgalo pulsado para conducir</translation>
    </message>
    <message>
        <source>%1% right, %2% forward</source>
        <translation>%1% derecha, %2% adelante</translation>
    </message>
    <message>
        <source>Speed limit %1 mm/s · deadband %2% · expo %3</source>
        <translation>Límite de velocidad %1 mm/s · zona muerta %2% · expo %3</translation>
    </message>
    <message>
        <source>Hold %1 to drive</source>
        <translation>Mantenga %1 para conducir</translation>
    </message>
    <message>
        <source>%1: Stop All</source>
        <translation>%1: Parar todo</translation>
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
        <translation>Arco adelante izquierda</translation>
    </message>
    <message>
        <source>Arc Forward Right</source>
        <translation>Arco adelante derecha</translation>
    </message>
    <message>
        <source>Arc Left</source>
        <translation>Arco izquierda</translation>
    </message>
    <message>
        <source>Arc Right</source>
        <translation>Arco derecha</translation>
    </message>
    <message>
        <source>Dock (reserved)</source>
        <translation>Base (reservado)</translation>
    </message>
    <message>
        <source>Download</source>
        <translation>Descargar</translation>
    </message>
    <message>
        <source>Drive Stop</source>
        <translation>Parar conducción</translation>
    </message>
    <message>
        <source>Fence</source>
        <translation>Valla</translation>
    </message>
    <message>
        <source>Force Field</source>
        <translation>Campo de fuerza</translation>
    </message>
    <message>
        <source>Forward</source>
        <translation>Adelante</translation>
    </message>
    <message>
        <source>Green Buoy</source>
        <translation>Boya verde</translation>
    </message>
    <message>
        <source>Large / Clean</source>
        <translation>Grande / Limpiar</translation>
    </message>
    <message>
        <source>Left</source>
        <translation>Izquierda</translation>
    </message>
    <message>
        <source>Max</source>
        <translation>Máx.</translation>
    </message>
    <message>
        <source>Medium</source>
        <translation>Mediano</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Ninguno</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pausa</translation>
    </message>
    <message>
        <source>Power</source>
        <translation>Encendido</translation>
    </message>
    <message>
        <source>Red Buoy</source>
        <translation>Boya roja</translation>
    </message>
    <message>
        <source>Right</source>
        <translation>Derecha</translation>
    </message>
    <message>
        <source>Seek Dock</source>
        <translation>Buscar base</translation>
    </message>
    <message>
        <source>Send All</source>
        <translation>Enviar todo</translation>
    </message>
    <message>
        <source>Small</source>
        <translation>Pequeño</translation>
    </message>
    <message>
        <source>Spot</source>
        <translation>Spot</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Parar</translation>
    </message>
    <message>
        <source>Virtual Wall</source>
        <translation>Pared virtual</translation>
    </message>
    <message>
        <source> and </source>
        <translation> y </translation>
    </message>
    <message>
        <source>Lighthouse (unbound) %1</source>
        <translation>Faro (sin asignar) %1</translation>
    </message>
    <message>
        <source>Lighthouse %1 %2</source>
        <translation>Faro %1 %2</translation>
    </message>
    <message>
        <source>IR %1</source>
        <translation>IR %1</translation>
    </message>
    <message>
        <source>Red</source>
        <comment>the dock&apos;s red buoy, in a small box</comment>
        <translation>Roja</translation>
    </message>
    <message>
        <source>Green</source>
        <comment>the dock&apos;s green buoy, in a small box</comment>
        <translation>Verde</translation>
    </message>
    <message>
        <source>Field</source>
        <comment>the dock&apos;s force field, in a small box</comment>
        <translation>Campo</translation>
    </message>
</context>
<context>
    <name>LanguageMenu</name>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Idioma</translation>
    </message>
    <message>
        <source>System default</source>
        <translation>Predeterminado del sistema</translation>
    </message>
</context>
<context>
    <name>LedEditor</name>
    <message>
        <source>Live</source>
        <translation>En vivo</translation>
    </message>
    <message>
        <source>Send changes as you make them, at most every %1 ms</source>
        <translation>Envía los cambios según los hace, como mucho cada %1 ms</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Aplicar</translation>
    </message>
    <message>
        <source>Will send:</source>
        <translation>Enviará:</translation>
    </message>
    <message>
        <source>7-segment display (163, 164)</source>
        <translation>Pantalla de 7 segmentos (163, 164)</translation>
    </message>
    <message>
        <source>Click a segment to switch it on or off</source>
        <translation>Haga clic en un segmento para encenderlo o apagarlo</translation>
    </message>
    <message>
        <source>Segment editor</source>
        <translation>Editor de segmentos</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Borrar</translation>
    </message>
    <message>
        <source>Switch every segment off</source>
        <translation>Apaga todos los segmentos</translation>
    </message>
    <message>
        <source>up to 4 characters</source>
        <translation>hasta 4 caracteres</translation>
    </message>
    <message>
        <source>Text for the display</source>
        <translation>Texto para la pantalla</translation>
    </message>
    <message>
        <source>The robot&apos;s approximation of the text</source>
        <translation>La aproximación del texto que hace el robot</translation>
    </message>
    <message>
        <source>What the robot shows</source>
        <translation>Lo que muestra el robot</translation>
    </message>
    <message>
        <source>&lt;b&gt;Segments&lt;/b&gt; (Digit LEDs Raw, 163): click to switch</source>
        <translation>&lt;b&gt;Segmentos&lt;/b&gt; (Digit LEDs Raw, 163): clic para cambiar</translation>
    </message>
    <message>
        <source>&lt;b&gt;Text&lt;/b&gt; (Digit LEDs ASCII, 164)</source>
        <translation>&lt;b&gt;Texto&lt;/b&gt; (Digit LEDs ASCII, 164)</translation>
    </message>
    <message>
        <source>What the robot shows:</source>
        <translation>Lo que muestra el robot:</translation>
    </message>
    <message>
        <source>LEDs (139)</source>
        <translation>LED (139)</translation>
    </message>
    <message>
        <source>Debris</source>
        <translation>Suciedad</translation>
    </message>
    <message>
        <source>Spot</source>
        <translation>Spot</translation>
    </message>
    <message>
        <source>Dock</source>
        <translation>Base</translation>
    </message>
    <message>
        <source>Check Robot</source>
        <translation>Revisar robot</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Reproducir</translation>
    </message>
    <message>
        <source>Advance</source>
        <translation>Avanzar</translation>
    </message>
    <message>
        <source>0 green … 255 red</source>
        <translation>0 verde … 255 rojo</translation>
    </message>
    <message>
        <source>Power colour</source>
        <translation>Color de encendido</translation>
    </message>
    <message>
        <source>Intensity</source>
        <translation>Intensidad</translation>
    </message>
    <message>
        <source>The power LED as set</source>
        <translation>El LED de encendido tal como está configurado</translation>
    </message>
    <message>
        <source>Power LED</source>
        <translation>LED de encendido</translation>
    </message>
    <message>
        <source>green</source>
        <translation>verde</translation>
    </message>
    <message>
        <source>red</source>
        <translation>rojo</translation>
    </message>
    <message>
        <source>off</source>
        <translation>apagado</translation>
    </message>
    <message>
        <source>full</source>
        <translation>máximo</translation>
    </message>
    <message>
        <source>Scheduling LEDs (162)</source>
        <translation>LED de programación (162)</translation>
    </message>
    <message>
        <source>Sun</source>
        <translation>Dom</translation>
    </message>
    <message>
        <source>Mon</source>
        <translation>Lun</translation>
    </message>
    <message>
        <source>Tue</source>
        <translation>Mar</translation>
    </message>
    <message>
        <source>Wed</source>
        <translation>Mié</translation>
    </message>
    <message>
        <source>Thu</source>
        <translation>Jue</translation>
    </message>
    <message>
        <source>Fri</source>
        <translation>Vie</translation>
    </message>
    <message>
        <source>Sat</source>
        <translation>Sáb</translation>
    </message>
    <message>
        <source>Schedule</source>
        <translation>Programación</translation>
    </message>
    <message>
        <source>Clock</source>
        <translation>Reloj</translation>
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
        <translation>Dos puntos</translation>
    </message>
    <message>
        <source>The %1 has no 7-segment display: Digit LEDs Raw (163) and Digit LEDs ASCII (164) are Roomba 500 / Create 2 only.</source>
        <translation>El %1 no tiene pantalla de 7 segmentos: Digit LEDs Raw (163) y Digit LEDs ASCII (164) son solo para Roomba 500 / Create 2.</translation>
    </message>
    <message>
        <source>⚠ Digit LEDs Raw (163) does not work in current Create 2 and Roomba 500/600 firmware. It is sent anyway; use Text (164) to be sure.</source>
        <translation>⚠ Digit LEDs Raw (163) no funciona con el firmware actual de Create 2 y Roomba 500/600. Se envía de todos modos; use Texto (164) para asegurarse.</translation>
    </message>
    <message>
        <source>%1.</source>
        <translation>%1.</translation>
    </message>
    <message>
        <source>Not sent: %1 outside ASCII 32..126. Use letters, digits and punctuation.</source>
        <translation>No enviado: %1 fuera de ASCII 32..126. Use letras, dígitos y signos de puntuación.</translation>
    </message>
    <message>
        <source>%1 shows blank: the robot has no shape for it.</source>
        <translation>%1 se muestra en blanco: el robot no tiene forma para ese carácter.</translation>
    </message>
    <message>
        <source>%1 show blank: the robot has no shape for them.</source>
        <translation>%1 se muestran en blanco: el robot no tiene forma para esos caracteres.</translation>
    </message>
    <message>
        <source>Colour %1 of 255 (green to red), intensity %2 of 255</source>
        <translation>Color %1 de 255 (de verde a rojo), intensidad %2 de 255</translation>
    </message>
    <message>
        <source>nothing (no changes since the last send)</source>
        <translation>nada (sin cambios desde el último envío)</translation>
    </message>
    <message>
        <source>Live mode sends changes as you make them</source>
        <translation>El modo en vivo envía los cambios según los hace</translation>
    </message>
    <message>
        <source>Send the changes shown under &quot;Will send&quot;</source>
        <translation>Envía los cambios que aparecen en «Enviará»</translation>
    </message>
    <message>
        <source>Dirt Detect</source>
        <translation>Detección de suciedad</translation>
    </message>
    <message>
        <source>Max</source>
        <translation>Máx.</translation>
    </message>
    <message>
        <source>Clean</source>
        <translation>Limpiar</translation>
    </message>
</context>
<context>
    <name>Lesson</name>
    <message>
        <source>Battery and current while driving</source>
        <translation>Batería y corriente al conducir</translation>
    </message>
    <message>
        <source>Where the energy goes: the battery&apos;s voltage, charge and current, standing and driving.</source>
        <translation>Adónde va la energía: tensión, carga y corriente de la batería, parado y en marcha.</translation>
    </message>
    <message>
        <source>The battery reports its voltage, its charge and the current flowing in or out of it. A negative current flows out of the battery. Keep the robot still, off the dock: the current stays small, above -400 mA, for two seconds.</source>
        <translation>La batería informa de su tensión, su carga y la corriente que entra o sale de ella. Una corriente negativa sale de la batería. Deja el robot quieto, fuera de la base: la corriente se mantiene pequeña, por encima de -400 mA, durante dos segundos.</translation>
    </message>
    <message>
        <source>Now drive. The wheel motors draw current from the battery, so the current goes further below zero. Keep driving until the current stays under -400 mA for two seconds.</source>
        <translation>Ahora conduce. Los motores de las ruedas toman corriente de la batería, así que la corriente baja más por debajo de cero. Sigue conduciendo hasta que la corriente se mantenga por debajo de -400 mA durante dos segundos.</translation>
    </message>
    <message>
        <source>Stop the robot. The motors stop drawing and the current comes back to what the robot needs to stand still: above -400 mA for two seconds. The voltage rises a little too.</source>
        <translation>Detén el robot. Los motores dejan de consumir y la corriente vuelve a lo que el robot necesita parado: por encima de -400 mA durante dos segundos. La tensión también sube un poco.</translation>
    </message>
    <message>
        <source>Bumpers and wheel drops</source>
        <translation>Parachoques y caída de ruedas</translation>
    </message>
    <message>
        <source>The switches that tell the robot it has hit something or lost the floor.</source>
        <translation>Los interruptores que avisan al robot de que ha chocado o ha perdido el suelo.</translation>
    </message>
    <message>
        <source>Put the robot back down, away from any wall. Every switch opens again: packet 7 reads 0 for a whole second.</source>
        <translation>Vuelve a dejar el robot en el suelo, lejos de las paredes. Todos los interruptores se abren de nuevo: el paquete 7 marca 0 durante un segundo entero.</translation>
    </message>
    <message>
        <source>Cliff sensors</source>
        <translation>Sensores de desnivel</translation>
    </message>
    <message>
        <source>Four infrared eyes under the bumper that keep the robot from falling down the stairs.</source>
        <translation>Cuatro ojos infrarrojos bajo el parachoques que evitan que el robot se caiga por las escaleras.</translation>
    </message>
    <message>
        <source>Under the front of the robot, four cliff sensors shine infrared light at the floor and measure how much comes back. On the floor each signal is high. Keep the robot on the floor and watch the front signals stay above 1000 for two seconds.</source>
        <translation>Bajo la parte delantera del robot, cuatro sensores de desnivel iluminan el suelo con luz infrarroja y miden cuánta vuelve. Sobre el suelo cada señal es alta. Deja el robot en el suelo y observa cómo las señales delanteras se mantienen por encima de 1000 durante dos segundos.</translation>
    </message>
    <message>
        <source>Encoders, distance and angle</source>
        <translation>Codificadores, distancia y ángulo</translation>
    </message>
    <message>
        <source>How the robot knows how far it drove and which way it points, and how wrong it gets.</source>
        <translation>Cómo sabe el robot cuánto ha avanzado y hacia dónde apunta, y cuánto se equivoca.</translation>
    </message>
    <message>
        <source>Each drive wheel turns an encoder that counts its steps. The dashboard adds up the steps of both wheels to work out how far the robot went: odometry. Drive straight ahead for one metre.</source>
        <translation>Cada rueda motriz gira un codificador que cuenta sus pasos. El panel suma los pasos de las dos ruedas para calcular cuánto ha avanzado el robot: la odometría. Conduce recto un metro.</translation>
    </message>
    <message>
        <source>Now turn on the spot, a quarter turn: 90 degrees. When one wheel goes forward and the other back, the difference between them is the angle. On the virtual robot, compare odometry with the way the robot truly points.</source>
        <translation>Ahora gira sobre el sitio un cuarto de vuelta: 90 grados. Cuando una rueda va hacia delante y la otra hacia atrás, la diferencia entre ellas es el ángulo. Con el robot virtual, compara la odometría con la dirección a la que apunta de verdad el robot.</translation>
    </message>
    <message>
        <source>Turn a whole circle, 360 degrees. Small errors add up: watch how far the odometry and the true turn drift apart.</source>
        <translation>Da una vuelta entera, 360 grados. Los errores pequeños se acumulan: observa cuánto se separan la odometría y el giro real.</translation>
    </message>
    <message>
        <source>IR from the dock and the virtual wall</source>
        <translation>IR de la base y de la pared virtual</translation>
    </message>
    <message>
        <source>Invisible beams that lead the robot home and keep it out.</source>
        <translation>Haces invisibles que llevan al robot a casa y lo mantienen fuera.</translation>
    </message>
    <message>
        <source>Light bumpers and wall following</source>
        <translation>Parachoques de luz y seguimiento de paredes</translation>
    </message>
    <message>
        <source>Seeing a wall before touching it, and keeping beside it.</source>
        <translation>Ver una pared antes de tocarla y mantenerse a su lado.</translation>
    </message>
    <message>
        <source>Each light bumper also has an on/off flag in packet 45, set when its signal is strong. Come close enough that the centre left and centre right flags are on together.</source>
        <translation>Cada parachoques de luz tiene además un indicador de encendido y apagado en el paquete 45, que se activa cuando su señal es fuerte. Acércate lo suficiente para que los indicadores central izquierdo y central derecho estén activos a la vez.</translation>
    </message>
    <message>
        <source>The bumper is one piece, but behind it sit two switches, one on the left and one on the right. Press the left half of the bumper gently. On the virtual robot, put its left front by a wall with the button below, then drive forward (Up arrow) until it touches.</source>
        <translation>El parachoques es una sola pieza, pero detrás hay dos interruptores, uno a la izquierda y otro a la derecha. Pulsa con suavidad la mitad izquierda del parachoques. Con el robot virtual, ponlo con su parte delantera izquierda junto a una pared con el botón de abajo y conduce hacia delante (flecha arriba) hasta que la toque.</translation>
    </message>
    <message>
        <source>Now press the right half of the bumper. On the virtual robot, put its right front by the wall with the button below and drive forward. Watch packet 7: the left bumper is one bit, the right bumper another.</source>
        <translation>Ahora pulsa la mitad derecha del parachoques. Con el robot virtual, ponlo con su parte delantera derecha junto a la pared con el botón de abajo y conduce hacia delante. Observa el paquete 7: el parachoques izquierdo es un bit y el derecho, otro.</translation>
    </message>
    <message>
        <source>Press the middle of the bumper, or drive straight into a wall: both switches close at once, and the robot knows the obstacle is straight ahead. On the virtual robot, face the wall with the button below, then drive forward.</source>
        <translation>Pulsa el centro del parachoques o conduce recto contra una pared: los dos interruptores se cierran a la vez y el robot sabe que el obstáculo está justo delante. Con el robot virtual, ponlo frente a la pared con el botón de abajo y conduce hacia delante.</translation>
    </message>
    <message>
        <source>Lift the robot a little off the floor. Each drive wheel drops down on its spring and closes a switch. Lift it until both wheels hang. In Safe mode the robot drops to Passive when its wheels drop: that is expected here. On the virtual robot, lift it with the button below.</source>
        <translation>Levanta un poco el robot del suelo. Cada rueda motriz baja con su muelle y cierra un interruptor. Levántalo hasta que cuelguen las dos ruedas. En modo Safe el robot pasa a Passive cuando caen sus ruedas: aquí es lo esperado. Con el robot virtual, levántalo con el botón de abajo.</translation>
    </message>
    <message>
        <source>Put its left front by a wall</source>
        <translation>Poner su frente izquierdo junto a una pared</translation>
    </message>
    <message>
        <source>Put its right front by the wall</source>
        <translation>Poner su frente derecho junto a la pared</translation>
    </message>
    <message>
        <source>Face the wall head on</source>
        <translation>Ponerlo de frente a la pared</translation>
    </message>
    <message>
        <source>Lift it off the floor</source>
        <translation>Levantarlo del suelo</translation>
    </message>
    <message>
        <source>Put it down in the open</source>
        <translation>Dejarlo en un sitio despejado</translation>
    </message>
    <message>
        <source>Drive slowly towards the edge of a table or a step, in Safe mode, or lift the front of the robot a little. On the virtual robot, carry it to the stage edge with the button below, then drive forward (Up arrow). When a front sensor loses the floor, the robot sets its cliff flag and, in Safe mode, stops and drops to Passive. A dark rug does the same, though the floor is there: then the signals stay low but well above 0 and no wheel drops. Either way, carry the robot back onto a light floor before you drive again.</source>
        <translation>Conduce despacio hacia el borde de una mesa o un escalón, en modo Safe, o levanta un poco la parte delantera del robot. Con el robot virtual, llévalo al borde del escenario con el botón de abajo y conduce hacia delante (flecha arriba). Cuando un sensor delantero pierde el suelo, el robot activa su indicador de desnivel y, en modo Safe, se detiene y pasa a Passive. Una alfombra oscura hace lo mismo, aunque el suelo esté ahí: entonces las señales se quedan bajas pero muy por encima de 0 y ninguna rueda cae. En ambos casos, lleva el robot a un suelo claro antes de volver a conducir.</translation>
    </message>
    <message>
        <source>Look at the signal behind the flag: over the edge almost no light comes back. The robot stopped, as the yellow line says; leave it in Passive for now and hold it a little further over the edge, so that a front signal stays under 500 for half a second. On the virtual robot, use the button below.</source>
        <translation>Mira la señal que hay detrás del indicador: sobre el borde casi no vuelve luz. El robot se ha detenido, como dice la línea amarilla; déjalo en Passive por ahora y sostenlo un poco más allá del borde, de modo que una señal delantera se mantenga por debajo de 500 durante medio segundo. Con el robot virtual, usa el botón de abajo.</translation>
    </message>
    <message>
        <source>Carry the robot back onto the floor, away from the edge. The flags clear and the signals rise again: both front signals above 1000 for one second. On the virtual robot, use the button below.</source>
        <translation>Lleva el robot de vuelta al suelo, lejos del borde. Los indicadores se apagan y las señales vuelven a subir: las dos señales delanteras por encima de 1000 durante un segundo. Con el robot virtual, usa el botón de abajo.</translation>
    </message>
    <message>
        <source>Carry it to face the stage edge</source>
        <translation>Llevarlo frente al borde del escenario</translation>
    </message>
    <message>
        <source>Hold it further over the edge</source>
        <translation>Sostenerlo más allá del borde</translation>
    </message>
    <message>
        <source>Carry it back onto the floor</source>
        <translation>Llevarlo de vuelta al suelo</translation>
    </message>
    <message>
        <source>The IR receiver at the front of the robot picks up infrared beams. The dock sends out two buoys, red and green, and a short force field. Place the robot a metre in front of the dock, facing it, until the receiver sees the dock. On the virtual robot, use the button below.</source>
        <translation>El receptor IR de la parte delantera del robot capta haces infrarrojos. La base emite dos boyas, roja y verde, y un campo de fuerza corto. Coloca el robot a un metro delante de la base, mirando hacia ella, hasta que el receptor vea la base. Con el robot virtual, usa el botón de abajo.</translation>
    </message>
    <message>
        <source>A virtual wall sends a beam that the robot will not cross. Bring the robot into the beam of the virtual wall: the virtual wall flag, packet 13, turns on. In the virtual classroom, the virtual wall stands on the front wall; the button below carries the robot into its beam.</source>
        <translation>Una pared virtual emite un haz que el robot no cruza. Lleva el robot al haz de la pared virtual: se activa el indicador de pared virtual, el paquete 13. En el aula virtual, la pared virtual está en la pared delantera; el botón de abajo lleva el robot a su haz.</translation>
    </message>
    <message>
        <source>Drive the robot onto the dock, nose first, following the buoys. When its contacts touch the dock, the home base shows up as a charging source. On the virtual robot, put it in front of the dock with the button below, then drive forward (Up arrow).</source>
        <translation>Conduce el robot hasta la base, de frente, siguiendo las boyas. Cuando sus contactos tocan la base, la base de carga aparece como fuente de carga. Con el robot virtual, ponlo delante de la base con el botón de abajo y conduce hacia delante (flecha arriba).</translation>
    </message>
    <message>
        <source>Put it a metre from the dock, facing it</source>
        <translation>Ponerlo a un metro de la base, mirando hacia ella</translation>
    </message>
    <message>
        <source>Carry it into the virtual wall&apos;s beam</source>
        <translation>Llevarlo al haz de la pared virtual</translation>
    </message>
    <message>
        <source>Put it in front of the dock</source>
        <translation>Ponerlo delante de la base</translation>
    </message>
    <message>
        <source>Six light bumpers look out through the window of the bumper. Each one shines infrared light and measures what a wall sends back. Move the robot slowly towards a wall, facing it, until the centre left signal is above 1000. On the virtual robot, face a wall with the button below, then drive forward (Up arrow).</source>
        <translation>Seis parachoques de luz miran a través de la ventana del parachoques. Cada uno emite luz infrarroja y mide lo que devuelve una pared. Acerca el robot despacio a una pared, mirando hacia ella, hasta que la señal central izquierda supere 1000. Con el robot virtual, ponlo frente a una pared con el botón de abajo y conduce hacia delante (flecha arriba).</translation>
    </message>
    <message>
        <source>The wall sensor on the right side looks sideways. Turn the robot so that the wall is on its right and drive along it, a few centimetres away. Keep the wall signal above 30 for three seconds. On the virtual robot, put it beside the wall with the button below, then drive forward.</source>
        <translation>El sensor de pared del lado derecho mira hacia un lado. Gira el robot para que la pared quede a su derecha y conduce a lo largo de ella, a unos centímetros. Mantén la señal de pared por encima de 30 durante tres segundos. Con el robot virtual, ponlo junto a la pared con el botón de abajo y conduce hacia delante.</translation>
    </message>
    <message>
        <source>Come closer to the wall, about four centimetres: the robot decides that a wall is there and sets the wall flag, packet 8. Keep it on for one second. On the virtual robot, use the button below.</source>
        <translation>Acércate más a la pared, unos cuatro centímetros: el robot decide que hay una pared y activa el indicador de pared, el paquete 8. Mantenlo activo durante un segundo. Con el robot virtual, usa el botón de abajo.</translation>
    </message>
    <message>
        <source>Face it to a wall</source>
        <translation>Ponerlo frente a una pared</translation>
    </message>
    <message>
        <source>Put it beside a wall, on its right</source>
        <translation>Ponerlo junto a una pared, a su derecha</translation>
    </message>
    <message>
        <source>Carry it 4 cm from the wall</source>
        <translation>Llevarlo a 4 cm de la pared</translation>
    </message>
</context>
<context>
    <name>LessonFile</name>
    <message>
        <source>must be &quot;%1&quot;</source>
        <translation>debe ser &quot;%1&quot;</translation>
    </message>
    <message>
        <source>%1 is not a version this program reads (it reads %2)</source>
        <translation>%1 no es una versión que este programa lea (lee la %2)</translation>
    </message>
    <message>
        <source>must be a list of at least one step</source>
        <translation>debe ser una lista con al menos un paso</translation>
    </message>
    <message>
        <source>has more than %1 steps</source>
        <translation>tiene más de %1 pasos</translation>
    </message>
    <message>
        <source>step %1</source>
        <translation>paso %1</translation>
    </message>
    <message>
        <source>must be an object</source>
        <translation>debe ser un objeto</translation>
    </message>
    <message>
        <source>%1 is not a part of the robot diagram (%2)</source>
        <translation>%1 no es una parte del dibujo del robot (%2)</translation>
    </message>
    <message>
        <source>%1 is not a packet key</source>
        <translation>%1 no es una clave de paquete</translation>
    </message>
    <message>
        <source>is missing or not an object</source>
        <translation>falta o no es un objeto</translation>
    </message>
    <message>
        <source>needs exactly one of &quot;packet&quot;, &quot;drive_mm&quot;, &quot;turn_degrees&quot;, &quot;any&quot; or &quot;all&quot;</source>
        <translation>necesita exactamente uno de &quot;packet&quot;, &quot;drive_mm&quot;, &quot;turn_degrees&quot;, &quot;any&quot; o &quot;all&quot;</translation>
    </message>
    <message>
        <source>must be a list of at least two goals</source>
        <translation>debe ser una lista con al menos dos objetivos</translation>
    </message>
    <message>
        <source>needs &quot;bit&quot;, &quot;above&quot;, &quot;below&quot;, &quot;equals&quot; or &quot;ir&quot; with &quot;packet&quot;</source>
        <translation>necesita &quot;bit&quot;, &quot;above&quot;, &quot;below&quot;, &quot;equals&quot; o &quot;ir&quot; junto a &quot;packet&quot;</translation>
    </message>
    <message>
        <source>%1 is not a bit of %2</source>
        <translation>%1 no es un bit de %2</translation>
    </message>
    <message>
        <source>%1 is not an IR kind (dock, virtual_wall or any)</source>
        <translation>%1 no es un tipo de IR (dock, virtual_wall o any)</translation>
    </message>
    <message>
        <source>needs an IR packet (ir_omni, ir_left or ir_right)</source>
        <translation>necesita un paquete IR (ir_omni, ir_left o ir_right)</translation>
    </message>
    <message>
        <source>is not a field of a lesson file</source>
        <translation>no es un campo de un archivo de lección</translation>
    </message>
    <message>
        <source>must be a text that is not empty</source>
        <translation>debe ser un texto no vacío</translation>
    </message>
    <message>
        <source>must be a list of texts</source>
        <translation>debe ser una lista de textos</translation>
    </message>
    <message>
        <source>%1 must be a number from %2 to %3</source>
        <translation>%1 debe ser un número de %2 a %3</translation>
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
        <translation>línea %1: %2</translation>
    </message>
    <message>
        <source>not a JSON object</source>
        <translation>no es un objeto JSON</translation>
    </message>
    <message>
        <source>needs &quot;place&quot; or &quot;forward_mm&quot;, not both</source>
        <translation>necesita &quot;place&quot; o &quot;forward_mm&quot;, no ambos</translation>
    </message>
    <message>
        <source>needs &quot;place&quot;, &quot;forward_mm&quot; or &quot;lift&quot;</source>
        <translation>necesita &quot;place&quot;, &quot;forward_mm&quot; o &quot;lift&quot;</translation>
    </message>
    <message>
        <source>must be [x_mm, y_mm, heading_degrees], x and y from -%1 to %1, the heading from -360 to 360</source>
        <translation>debe ser [x_mm, y_mm, rumbo_grados], x e y de -%1 a %1, el rumbo de -360 a 360</translation>
    </message>
    <message>
        <source>must be true or false</source>
        <translation>debe ser true o false</translation>
    </message>
    <message>
        <source>%1 or %2</source>
        <translation>%1 o %2</translation>
    </message>
    <message>
        <source>%1 is not a robot (%2)</source>
        <translation>%1 no es un robot (%2)</translation>
    </message>
</context>
<context>
    <name>LessonPanel</name>
    <message>
        <source>This lesson cannot be opened: %1</source>
        <translation>No se puede abrir esta lección: %1</translation>
    </message>
    <message>
        <source>Open lesson</source>
        <translation>Abrir lección</translation>
    </message>
    <message>
        <source>Lessons (*.json);;All files (*)</source>
        <translation>Lecciones (*.json);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>Choose a lesson…</source>
        <translation>Elige una lección…</translation>
    </message>
    <message>
        <source>Choose a lesson above, or open a lesson file. Each step says what to do and turns green when the robot shows it was done.</source>
        <translation>Elige una lección arriba o abre un archivo de lección. Cada paso dice qué hacer y se pone verde cuando el robot muestra que se ha hecho.</translation>
    </message>
    <message>
        <source>Lesson complete: every step is done. Well done!</source>
        <translation>Lección completada: todos los pasos están hechos. ¡Bien hecho!</translation>
    </message>
    <message>
        <source>This lesson needs a robot this one is not (%1): some goals cannot be met.</source>
        <translation>Esta lección necesita otro robot (%1): algunos objetivos no se pueden cumplir.</translation>
    </message>
    <message>
        <source>No robot is selected: the goals are checked on the selected robot&apos;s data.</source>
        <translation>No hay ningún robot seleccionado: los objetivos se comprueban con los datos del robot seleccionado.</translation>
    </message>
    <message>
        <source>Open lesson file…</source>
        <translation>Abrir archivo de lección…</translation>
    </message>
    <message>
        <source>◀ Back</source>
        <translation>◀ Atrás</translation>
    </message>
    <message>
        <source>Skip ▶</source>
        <translation>Saltar ▶</translation>
    </message>
    <message>
        <source>Restart</source>
        <translation>Reiniciar</translation>
    </message>
    <message>
        <source>Lesson</source>
        <translation>Lección</translation>
    </message>
    <message>
        <source>Lesson steps</source>
        <translation>Pasos de la lección</translation>
    </message>
</context>
<context>
    <name>LessonStepView</name>
    <message>
        <source>Step %1 of %2</source>
        <translation>Paso %1 de %2</translation>
    </message>
    <message>
        <source>Goal: %1</source>
        <translation>Objetivo: %1</translation>
    </message>
    <message>
        <source>only on the virtual robot</source>
        <translation>solo con el robot virtual</translation>
    </message>
    <message>
        <source>none</source>
        <translation>ninguno</translation>
    </message>
    <message>
        <source> or </source>
        <translation> o </translation>
    </message>
    <message>
        <source> and </source>
        <translation> y </translation>
    </message>
    <message>
        <source>drive %1 mm</source>
        <translation>avanzar %1 mm</translation>
    </message>
    <message>
        <source>turn %1°</source>
        <translation>girar %1°</translation>
    </message>
    <message>
        <source>%1 (this robot has no such sensor)</source>
        <translation>%1 (este robot no tiene ese sensor)</translation>
    </message>
    <message>
        <source>%1 on</source>
        <translation>%1 activo</translation>
    </message>
    <message>
        <source>%1 between %2 and %3</source>
        <translation>%1 entre %2 y %3</translation>
    </message>
    <message>
        <source>%1 above %2</source>
        <translation>%1 por encima de %2</translation>
    </message>
    <message>
        <source>%1 below %2</source>
        <translation>%1 por debajo de %2</translation>
    </message>
    <message>
        <source>%1 = %2</source>
        <translation>%1 = %2</translation>
    </message>
    <message>
        <source>%1 sees the dock</source>
        <translation>%1 ve la base</translation>
    </message>
    <message>
        <source>%1 sees a virtual wall</source>
        <translation>%1 ve una pared virtual</translation>
    </message>
    <message>
        <source>%1 sees any IR</source>
        <translation>%1 ve cualquier IR</translation>
    </message>
    <message>
        <source>%1 for %2 s</source>
        <translation>%1 durante %2 s</translation>
    </message>
    <message>
        <source>Driven, by odometry</source>
        <translation>Recorrido, según la odometría</translation>
    </message>
    <message>
        <source>Turned, by odometry</source>
        <translation>Girado, según la odometría</translation>
    </message>
    <message>
        <source>Driven, true</source>
        <translation>Recorrido, real</translation>
    </message>
    <message>
        <source>Turned, true</source>
        <translation>Girado, real</translation>
    </message>
    <message>
        <source>%p %</source>
        <translation>%p %</translation>
    </message>
    <message>
        <source>Done · next in %1 s</source>
        <translation>Hecho · siguiente en %1 s</translation>
    </message>
    <message>
        <source>On the virtual robot: %1</source>
        <translation>En el robot virtual: %1</translation>
    </message>
</context>
<context>
    <name>LinkSettings</name>
    <message>
        <source>replay of %1</source>
        <translation>reproducción de %1</translation>
    </message>
    <message>
        <source>virtual %1</source>
        <translation>%1 virtual</translation>
    </message>
    <message>
        <source>%1 on the broker</source>
        <translation>%1 en el bróker</translation>
    </message>
    <message>
        <source>%1: Baud is not sent over raw TCP: the bridge&apos;s serial rate cannot follow, and the robot would talk at a rate the bridge does not. Set the serial port&apos;s rate in ser2net&apos;s config instead (for example 115200 to 19200 on the robot&apos;s port line), then reconnect with the new rate; or use the bridge in RFC 2217 (telnet) mode, where the rate follows</source>
        <translation>%1: Baud no se envía por TCP sin procesar: la velocidad serie del puente no puede seguirla, y el robot hablaría a una velocidad que el puente no habla. Cambie en su lugar la velocidad del puerto serie en la configuración de ser2net (por ejemplo, 115200 por 19200 en la línea del puerto del robot) y vuelva a conectar con la nueva velocidad; o use el puente en modo RFC 2217 (telnet), donde la velocidad sigue</translation>
    </message>
</context>
<context>
    <name>LiveServerActions</name>
    <message>
        <source>Live data server: dropped %1: %2</source>
        <translation>Servidor de datos en vivo: %1 desconectado: %2</translation>
    </message>
    <message>
        <source>Live data server: refused %1, which %2; Foxglove, Lichtblick and PlotJuggler offer the right protocol</source>
        <translation>Servidor de datos en vivo: %1 rechazado (%2); Foxglove, Lichtblick y PlotJuggler ofrecen el protocolo correcto</translation>
    </message>
    <message>
        <source>Live data server on %1: connect Foxglove or Lichtblick to it.</source>
        <translation>Servidor de datos en vivo en %1: conecte Foxglove o Lichtblick a él.</translation>
    </message>
    <message>
        <source>Live data server on %1, reachable from other machines: anyone on the network can watch the robots.</source>
        <translation>Servidor de datos en vivo en %1, accesible desde otros equipos: cualquiera en la red puede ver los robots.</translation>
    </message>
    <message>
        <source>Live data server stopped.</source>
        <translation>Servidor de datos en vivo detenido.</translation>
    </message>
    <message>
        <source>Address to paste into Foxglove or Lichtblick (Open connection → Foxglove WebSocket): %1</source>
        <translation>Dirección para pegar en Foxglove o Lichtblick (Open connection → Foxglove WebSocket): %1</translation>
    </message>
    <message>
        <source>Not serving.</source>
        <translation>Inactivo.</translation>
    </message>
    <message>
        <source>Not serving: %1</source>
        <translation>Inactivo: %1</translation>
    </message>
    <message>
        <source>Clients connected: %1</source>
        <translation>Clientes conectados: %1</translation>
    </message>
    <message>
        <source>Still serving on the address before: %1</source>
        <translation>Sigue sirviendo en la dirección anterior: %1</translation>
    </message>
    <message>
        <source>Only programs on this computer can connect.</source>
        <translation>Solo los programas de este equipo pueden conectarse.</translation>
    </message>
    <message>
        <source>Reachable from other computers, as asked: anyone on the network can watch the robots. Use 127.0.0.1 to keep it on this computer.</source>
        <translation>Accesible desde otros equipos, como se pidió: cualquiera en la red puede ver los robots. Use 127.0.0.1 para mantenerlo en este equipo.</translation>
    </message>
    <message>
        <source>&amp;Live data server…</source>
        <translation>Servidor de datos en &amp;vivo…</translation>
    </message>
    <message>
        <source>Live data server</source>
        <translation>Servidor de datos en vivo</translation>
    </message>
    <message>
        <source>Serves every robot&apos;s telemetry, pose, events and markers over the Foxglove WebSocket protocol, for Foxglove, Lichtblick and PlotJuggler.</source>
        <translation>Sirve la telemetría, la pose, los eventos y las marcas de cada robot por el protocolo Foxglove WebSocket, para Foxglove, Lichtblick y PlotJuggler.</translation>
    </message>
    <message>
        <source>Serve live data</source>
        <translation>Servir datos en vivo</translation>
    </message>
    <message>
        <source>Address and port:</source>
        <translation>Dirección y puerto:</translation>
    </message>
    <message>
        <source>Messages a second per channel:</source>
        <translation>Mensajes por segundo y canal:</translation>
    </message>
    <message>
        <source>Live data server: %1. The robots go on without it; choose another port in View → Live data server….</source>
        <translation>Servidor de datos en vivo: %1. Los robots siguen sin él; elija otro puerto en Ver → Servidor de datos en vivo….</translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <source>Connection</source>
        <translation>Conexión</translation>
    </message>
    <message>
        <source>Modes</source>
        <translation>Modos</translation>
    </message>
    <message>
        <source>Drive</source>
        <translation>Conducir</translation>
    </message>
    <message>
        <source>Gauges</source>
        <translation>Indicadores</translation>
    </message>
    <message>
        <source>Signals</source>
        <translation>Señales</translation>
    </message>
    <message>
        <source>Plots</source>
        <translation>Gráficas</translation>
    </message>
    <message>
        <source>Inspector</source>
        <translation>Inspector</translation>
    </message>
    <message>
        <source>Songs</source>
        <translation>Canciones</translation>
    </message>
    <message>
        <source>LEDs and digits</source>
        <translation>LED y dígitos</translation>
    </message>
    <message>
        <source>Schedule</source>
        <translation>Programación</translation>
    </message>
    <message>
        <source>Script</source>
        <translation>Script</translation>
    </message>
    <message>
        <source>Motors and outputs</source>
        <translation>Motores y salidas</translation>
    </message>
    <message>
        <source>Odometry map</source>
        <translation>Mapa de odometría</translation>
    </message>
    <message>
        <source>Gamepad</source>
        <translation>Mando</translation>
    </message>
    <message>
        <source>About Roomba Dashboard</source>
        <translation>Acerca de Roomba Dashboard</translation>
    </message>
    <message>
        <source>Roomba Dashboard %1
A dashboard for iRobot robots that speak the Open Interface.
GPL-3.0-or-later.</source>
        <translation>Roomba Dashboard %1
Un panel de control para robots iRobot que hablan el Open Interface.
GPL-3.0-or-later.</translation>
    </message>
    <message>
        <source>Roomba Dashboard</source>
        <translation>Roomba Dashboard</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Archivo</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Salir</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ver</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>Ay&amp;uda</translation>
    </message>
    <message>
        <source>&amp;About</source>
        <translation>&amp;Acerca de</translation>
    </message>
    <message>
        <source>%1 — Roomba Dashboard</source>
        <translation>%1 — Roomba Dashboard</translation>
    </message>
    <message>
        <source>Lesson</source>
        <translation>Lección</translation>
    </message>
    <message>
        <source>&amp;Robot</source>
        <translation>&amp;Robot</translation>
    </message>
    <message>
        <source>Markers</source>
        <translation>Marcas</translation>
    </message>
    <message>
        <source>Typed into a text field: click the robot diagram or press Esc to drive with the keys</source>
        <translation>Escrito en un campo de texto: haga clic en el dibujo del robot o pulse Esc para conducir con las teclas</translation>
    </message>
    <message>
        <source>Typed into “%1”: click the robot diagram or press Esc to drive with the keys</source>
        <translation>Escrito en «%1»: haga clic en el dibujo del robot o pulse Esc para conducir con las teclas</translation>
    </message>
</context>
<context>
    <name>MarkerActions</name>
    <message>
        <source>Mark</source>
        <translation>Marcar</translation>
    </message>
    <message>
        <source>Drop a marker on the recording here, with an optional note (M)</source>
        <translation>Poner aquí una marca en la grabación, con una nota opcional (M)</translation>
    </message>
    <message>
        <source>Markers are kept in a recording: start one (File → Record) or open one. Then M marks the moment.</source>
        <translation>Las marcas se guardan en una grabación: inicie una (Archivo → Grabar) o abra una. Después, M marca el momento.</translation>
    </message>
    <message>
        <source>Marker %1 at %2:</source>
        <translation>Marca %1 en %2:</translation>
    </message>
    <message>
        <source>Lesson step %1 done</source>
        <translation>Paso %1 de la lección hecho</translation>
    </message>
    <message>
        <source>Mark &amp;this moment</source>
        <translation>Marcar es&amp;te momento</translation>
    </message>
    <message>
        <source>Previo&amp;us marker</source>
        <translation>Marca &amp;anterior</translation>
    </message>
    <message>
        <source>&amp;Next marker</source>
        <translation>Marca s&amp;iguiente</translation>
    </message>
</context>
<context>
    <name>MarkerList</name>
    <message>
        <source>Time</source>
        <translation>Tiempo</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>Nota</translation>
    </message>
    <message>
        <source>&amp;Jump</source>
        <translation>&amp;Ir</translation>
    </message>
    <message>
        <source>Go to the selected marker in the replay</source>
        <translation>Ir a la marca seleccionada en la reproducción</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Borrar</translation>
    </message>
    <message>
        <source>Delete the selected marker</source>
        <translation>Borrar la marca seleccionada</translation>
    </message>
</context>
<context>
    <name>MarkerNoteEditor</name>
    <message>
        <source>a short note, then Enter</source>
        <translation>una nota breve y luego Intro</translation>
    </message>
    <message>
        <source>The marker is already set; a note is optional</source>
        <translation>La marca ya está puesta; la nota es opcional</translation>
    </message>
</context>
<context>
    <name>MeasuredMove</name>
    <message>
        <source>Forward</source>
        <translation>Adelante</translation>
    </message>
    <message>
        <source>Backward</source>
        <translation>Atrás</translation>
    </message>
    <message>
        <source>Turn left</source>
        <translation>Girar a la izquierda</translation>
    </message>
    <message>
        <source>Turn right</source>
        <translation>Girar a la derecha</translation>
    </message>
    <message>
        <source>Go</source>
        <translation>Ir</translation>
    </message>
    <message>
        <source>The robot drives until its wheels have measured the distance or the turn, then stops. Space or Esc stops it sooner.</source>
        <translation>El robot avanza hasta que sus ruedas han medido la distancia o el giro, y entonces se detiene. Espacio o Esc lo detienen antes.</translation>
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
        <translation>Moverse con exactitud:</translation>
    </message>
    <message>
        <source>A move measured by the robot&apos;s own wheels, as a student&apos;s program makes it.</source>
        <translation>Un movimiento medido por las propias ruedas del robot, como lo hace el programa de un estudiante.</translation>
    </message>
</context>
<context>
    <name>MeasuredMoves</name>
    <message>
        <source>Not moving: a classroom robot&apos;s measured moves run on its bridge, beside the robot (the Python library&apos;s straight() and turn()). Drive it with the pad or the keys here.</source>
        <translation>Sin movimiento: los movimientos medidos de un robot del aula se ejecutan en su puente, junto al robot (straight() y turn() de la biblioteca de Python). Condúzcalo aquí con el panel o las teclas.</translation>
    </message>
    <message>
        <source>Not moving: no live data from the robot, so its wheels cannot measure the move. Connect it and wait until it streams.</source>
        <translation>Sin movimiento: no llegan datos en vivo del robot, así que sus ruedas no pueden medir el movimiento. Conéctelo y espere a que transmita.</translation>
    </message>
    <message>
        <source>Not moving: the robot&apos;s model is not known yet. Wait a moment and press Go again.</source>
        <translation>Sin movimiento: aún no se conoce el modelo del robot. Espere un momento y pulse Ir de nuevo.</translation>
    </message>
    <message>
        <source>Not moving: the robot is in Passive mode and ignores motion. Press Enter Safe, then Go.</source>
        <translation>Sin movimiento: el robot está en modo Pasivo e ignora el movimiento. Pulse Pasar a Safe y luego Ir.</translation>
    </message>
    <message>
        <source>Moving %1 mm at %2 mm/s…</source>
        <translation>Moviéndose %1 mm a %2 mm/s…</translation>
    </message>
    <message>
        <source>Turning %1° at %2°/s…</source>
        <translation>Girando %1° a %2°/s…</translation>
    </message>
    <message>
        <source>%1 mm measured</source>
        <translation>%1 mm medidos</translation>
    </message>
    <message>
        <source>%1° measured</source>
        <translation>%1° medidos</translation>
    </message>
    <message>
        <source>Done: asked %1 mm, %2.</source>
        <translation>Hecho: se pidieron %1 mm, %2.</translation>
    </message>
    <message>
        <source>Done: asked %1°, %2.</source>
        <translation>Hecho: se pidieron %1°, %2.</translation>
    </message>
    <message>
        <source>Stopped early by the robot itself (a cliff or a wheel drop; the Modes dock says which): %1.</source>
        <translation>Detenido antes por el propio robot (un desnivel o una rueda caída; el panel Modos dice cuál): %1.</translation>
    </message>
    <message>
        <source>Stopped early: another command or a stop ended the move (%1).</source>
        <translation>Detenido antes: otra orden o una parada terminó el movimiento (%1).</translation>
    </message>
    <message>
        <source>Stopped: the move took too long, as if the robot pushed against something (%1). Look at what is in its way.</source>
        <translation>Detenido: el movimiento tardó demasiado, como si el robot empujara contra algo (%1). Mire qué tiene en su camino.</translation>
    </message>
    <message>
        <source>Stopped: the robot&apos;s data stopped coming (%1). Check its connection.</source>
        <translation>Detenido: los datos del robot dejaron de llegar (%1). Compruebe su conexión.</translation>
    </message>
</context>
<context>
    <name>MidiMelody</name>
    <message>
        <source>Could not import %1: %2</source>
        <translation>No se pudo importar %1: %2</translation>
    </message>
    <message>
        <source>not a readable Standard MIDI File</source>
        <translation>no es un archivo MIDI estándar legible</translation>
    </message>
    <message>
        <source>it has no notes</source>
        <translation>no tiene notas</translation>
    </message>
    <message>
        <source>its notes are all shorter than 1/64 s</source>
        <translation>todas sus notas duran menos de 1/64 s</translation>
    </message>
</context>
<context>
    <name>ModePanel</name>
    <message>
        <source>Off</source>
        <translation>Apagado</translation>
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
        <translation>¿Pasar al modo Full?</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Iniciar</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Detener</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Reiniciar</translation>
    </message>
    <message>
        <source>Power off</source>
        <translation>Apagar</translation>
    </message>
    <message>
        <source>Clean</source>
        <translation>Limpiar</translation>
    </message>
    <message>
        <source>Spot</source>
        <translation>Spot</translation>
    </message>
    <message>
        <source>Max</source>
        <translation>Máx.</translation>
    </message>
    <message>
        <source>Seek Dock</source>
        <translation>Buscar base</translation>
    </message>
    <message>
        <source>Cover</source>
        <translation>Cubrir</translation>
    </message>
    <message>
        <source>Cover and Dock</source>
        <translation>Cubrir y volver a la base</translation>
    </message>
    <message>
        <source>Demo</source>
        <translation>Demo</translation>
    </message>
    <message>
        <source>Demo to run</source>
        <translation>Demo que se ejecutará</translation>
    </message>
    <message>
        <source>%1 (opcode %2)</source>
        <translation>%1 (código de operación %2)</translation>
    </message>
    <message>
        <source>%1 is not available on the %2</source>
        <translation>%1 no está disponible en el %2</translation>
    </message>
    <message>
        <source>Mode: %1</source>
        <translation>Modo: %1</translation>
    </message>
    <message>
        <source>Mode: unknown</source>
        <translation>Modo: desconocido</translation>
    </message>
    <message>
        <source>Firmware: %1</source>
        <translation>Firmware: %1</translation>
    </message>
    <message>
        <source>mode %1 (not an OI mode)</source>
        <translation>modo %1 (no es un modo OI)</translation>
    </message>
    <message>
        <source>Full mode turns off the cliff, wheel-drop and charger safety stops. The robot will drive off a table edge if told to. It is also the way off the dock, where Safe is refused (on the dock it does not charge in Full). Enter Full mode?</source>
        <translation>El modo Full desactiva las paradas de seguridad por precipicio, rueda caída y cargador. El robot se saldrá del borde de una mesa si se le ordena. También es la forma de sacarlo de la base, donde Safe se rechaza (en la base no carga en Full). ¿Entrar en modo Full?</translation>
    </message>
</context>
<context>
    <name>MotorsPanel</name>
    <message>
        <source>Motors</source>
        <translation>Motores</translation>
    </message>
    <message>
        <source>PWM Motors</source>
        <translation>Motores PWM</translation>
    </message>
    <message>
        <source>Buttons</source>
        <translation>Botones</translation>
    </message>
    <message>
        <source>Low Side Drivers</source>
        <translation>Controladores de lado bajo</translation>
    </message>
    <message>
        <source>PWM Low Side Drivers</source>
        <translation>Controladores de lado bajo PWM</translation>
    </message>
    <message>
        <source>Digital Outputs</source>
        <translation>Salidas digitales</translation>
    </message>
    <message>
        <source>Send IR</source>
        <translation>Enviar IR</translation>
    </message>
    <message>
        <source>Clean</source>
        <translation>Limpiar</translation>
    </message>
    <message>
        <source>Spot</source>
        <translation>Spot</translation>
    </message>
    <message>
        <source>Dock</source>
        <translation>Base</translation>
    </message>
    <message>
        <source>Minute</source>
        <translation>Minuto</translation>
    </message>
    <message>
        <source>Hour</source>
        <translation>Hora</translation>
    </message>
    <message>
        <source>Day</source>
        <translation>Día</translation>
    </message>
    <message>
        <source>Schedule</source>
        <translation>Programación</translation>
    </message>
    <message>
        <source>Clock</source>
        <translation>Reloj</translation>
    </message>
    <message>
        <source>Brushes and vacuum — Motors (138)</source>
        <translation>Cepillos y aspiración — Motores (138)</translation>
    </message>
    <message>
        <source>Main brush</source>
        <translation>Cepillo principal</translation>
    </message>
    <message>
        <source>Outward</source>
        <translation>Hacia fuera</translation>
    </message>
    <message>
        <source>Side brush</source>
        <translation>Cepillo lateral</translation>
    </message>
    <message>
        <source>Clockwise</source>
        <translation>Sentido horario</translation>
    </message>
    <message>
        <source>Vacuum</source>
        <translation>Aspiración</translation>
    </message>
    <message>
        <source>Duty cycle — PWM Motors (144)</source>
        <translation>Ciclo de trabajo — Motores PWM (144)</translation>
    </message>
    <message>
        <source>Brushes -127..127 (negative turns them the other way), vacuum 0..127; 127 is full power.</source>
        <translation>Cepillos -127..127 (negativo los gira al revés), aspiración 0..127; 127 es la potencia máxima.</translation>
    </message>
    <message>
        <source>Press a button — Buttons (165)</source>
        <translation>Pulsar un botón — Botones (165)</translation>
    </message>
    <message>
        <source>Low side drivers — Low Side Drivers (138)</source>
        <translation>Controladores de lado bajo — Controladores de lado bajo (138)</translation>
    </message>
    <message>
        <source>Duty cycle — PWM Low Side Drivers (144)</source>
        <translation>Ciclo de trabajo — Controladores de lado bajo PWM (144)</translation>
    </message>
    <message>
        <source>LD%1</source>
        <translation>LD%1</translation>
    </message>
    <message>
        <source>0..128; 128 is 100%.</source>
        <translation>0..128; 128 es el 100 %.</translation>
    </message>
    <message>
        <source>Cargo bay — Digital Outputs (147)</source>
        <translation>Bahía de carga — Salidas digitales (147)</translation>
    </message>
    <message>
        <source>Output %1</source>
        <translation>Salida %1</translation>
    </message>
    <message>
        <source>IR output — Send IR (151)</source>
        <translation>Salida IR — Enviar IR (151)</translation>
    </message>
    <message>
        <source>Byte</source>
        <translation>Byte</translation>
    </message>
    <message>
        <source>All off</source>
        <translation>Apagar todo</translation>
    </message>
    <message>
        <source>Not on the %1, so not shown: %2.</source>
        <translation>No existen en el %1, por lo que no se muestran: %2.</translation>
    </message>
    <message>
        <source>Last sent: —</source>
        <translation>Último envío: —</translation>
    </message>
    <message>
        <source>Last sent: %1</source>
        <translation>Último envío: %1</translation>
    </message>
</context>
<context>
    <name>NetworkTransport</name>
    <message>
        <source>%1 on the broker</source>
        <translation>%1 en el bróker</translation>
    </message>
    <message>
        <source>%1: not connected to a broker</source>
        <translation>%1: sin conexión con un bróker</translation>
    </message>
    <message>
        <source>%1: the bridge takes commands, not bytes: check the connection where the bridge runs</source>
        <translation>%1: el puente acepta órdenes, no bytes: compruebe la conexión donde se ejecuta el puente</translation>
    </message>
    <message>
        <source>%1: control was not given</source>
        <translation>%1: no se concedió el control</translation>
    </message>
    <message>
        <source>%1: %2 has control</source>
        <translation>%1: %2 tiene el control</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1: the bridge does not publish packet %2, so the query cannot be answered</source>
        <translation>%1: el puente no publica el paquete %2, así que la consulta no puede responderse</translation>
    </message>
    <message>
        <source>%1: the bridge does not read the robot&apos;s script back</source>
        <translation>%1: el puente no lee el script del robot</translation>
    </message>
</context>
<context>
    <name>OdometryMap</name>
    <message>
        <source>Zoom in</source>
        <translation>Acercar</translation>
    </message>
    <message>
        <source>Zoom out</source>
        <translation>Alejar</translation>
    </message>
    <message>
        <source>Centre</source>
        <translation>Centrar</translation>
    </message>
    <message>
        <source>Centre the map on the robot</source>
        <translation>Centra el mapa en el robot</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Reiniciar</translation>
    </message>
    <message>
        <source>Clear the trail and start the odometry again at the origin</source>
        <translation>Borra el rastro y reinicia la odometría en el origen</translation>
    </message>
    <message>
        <source>Wheel base</source>
        <translation>Distancia entre ruedas</translation>
    </message>
    <message>
        <source>Wheel Ø</source>
        <translation>Ø de rueda</translation>
    </message>
    <message>
        <source>Odometry map</source>
        <translation>Mapa de odometría</translation>
    </message>
    <message>
        <source>The %1 has no wheel encoders; it reports distance and angle itself</source>
        <translation>El %1 no tiene codificadores de rueda; informa él mismo de la distancia y el ángulo</translation>
    </message>
    <message>
        <source>Distance between the wheels&apos; contact points</source>
        <translation>Distancia entre los puntos de contacto de las ruedas</translation>
    </message>
    <message>
        <source>Wheel diameter; 508.8 encoder counts are one turn</source>
        <translation>Diámetro de rueda; 508.8 cuentas del codificador son una vuelta</translation>
    </message>
    <message>
        <source>x %1 mm   y %2 mm   θ %3°</source>
        <translation>x %1 mm   y %2 mm   θ %3°</translation>
    </message>
    <message>
        <source>   drift %1 mm</source>
        <translation>   deriva %1 mm</translation>
    </message>
    <message>
        <source>Robot at x %1 mm, y %2 mm, heading %3 degrees</source>
        <translation>Robot en x %1 mm, y %2 mm, rumbo %3 grados</translation>
    </message>
    <message>
        <source>; %1 mm from the true pose</source>
        <translation>; a %1 mm de la pose real</translation>
    </message>
    <message>
        <source>odometry</source>
        <translation>odometría</translation>
    </message>
    <message>
        <source>true pose</source>
        <translation>pose real</translation>
    </message>
    <message>
        <source>dock</source>
        <translation>base</translation>
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
        <translation>Editar sala</translation>
    </message>
    <message>
        <source>Move, add and delete the walls, stage edges, the dock and the virtual wall</source>
        <translation>Mover, añadir y borrar las paredes, los bordes del escenario, la base y la pared virtual</translation>
    </message>
    <message>
        <source>Robot not yet identified: a Roomba 500 or a Create 2? Until it is named, its wheel counts may read mirrored, so no path is drawn.</source>
        <translation>Robot aún sin identificar: ¿un Roomba 500 o un Create 2? Hasta que se indique, sus contadores de rueda pueden leerse al revés, así que no se dibuja ningún recorrido.</translation>
    </message>
    <message>
        <source>comparison run</source>
        <translation>recorrido de comparación</translation>
    </message>
    <message>
        <source>wall</source>
        <translation>pared</translation>
    </message>
    <message>
        <source>stage edge</source>
        <translation>borde del escenario</translation>
    </message>
    <message>
        <source>virtual wall</source>
        <translation>pared virtual</translation>
    </message>
</context>
<context>
    <name>PacketName</name>
    <message>
        <source>Angle</source>
        <translation>Ángulo</translation>
    </message>
    <message>
        <source>Battery Capacity</source>
        <translation>Capacidad de la batería</translation>
    </message>
    <message>
        <source>Battery Charge</source>
        <translation>Carga de la batería</translation>
    </message>
    <message>
        <source>Bumps and Wheel Drops</source>
        <translation>Choques y caídas de rueda</translation>
    </message>
    <message>
        <source>Buttons</source>
        <translation>Botones</translation>
    </message>
    <message>
        <source>Cargo Bay Analog Signal</source>
        <translation>Señal analógica de la bahía de carga</translation>
    </message>
    <message>
        <source>Cargo Bay Digital Inputs</source>
        <translation>Entradas digitales de la bahía de carga</translation>
    </message>
    <message>
        <source>Charging Sources Available</source>
        <translation>Fuentes de carga disponibles</translation>
    </message>
    <message>
        <source>Charging State</source>
        <translation>Estado de carga</translation>
    </message>
    <message>
        <source>Cliff Front Left</source>
        <translation>Desnivel delantero izquierdo</translation>
    </message>
    <message>
        <source>Cliff Front Left Signal</source>
        <translation>Señal de desnivel delantero izquierdo</translation>
    </message>
    <message>
        <source>Cliff Front Right</source>
        <translation>Desnivel delantero derecho</translation>
    </message>
    <message>
        <source>Cliff Front Right Signal</source>
        <translation>Señal de desnivel delantero derecho</translation>
    </message>
    <message>
        <source>Cliff Left</source>
        <translation>Desnivel izquierdo</translation>
    </message>
    <message>
        <source>Cliff Left Signal</source>
        <translation>Señal de desnivel izquierdo</translation>
    </message>
    <message>
        <source>Cliff Right</source>
        <translation>Desnivel derecho</translation>
    </message>
    <message>
        <source>Cliff Right Signal</source>
        <translation>Señal de desnivel derecho</translation>
    </message>
    <message>
        <source>Current</source>
        <translation>Corriente</translation>
    </message>
    <message>
        <source>Dirt Detect</source>
        <translation>Detección de suciedad</translation>
    </message>
    <message>
        <source>Distance</source>
        <translation>Distancia</translation>
    </message>
    <message>
        <source>Infrared Character Left</source>
        <translation>Carácter infrarrojo izquierdo</translation>
    </message>
    <message>
        <source>Infrared Character Right</source>
        <translation>Carácter infrarrojo derecho</translation>
    </message>
    <message>
        <source>Left Encoder Counts</source>
        <translation>Cuentas del codificador izquierdo</translation>
    </message>
    <message>
        <source>Left Motor Current</source>
        <translation>Corriente del motor izquierdo</translation>
    </message>
    <message>
        <source>Light Bump Center Left Signal</source>
        <translation>Señal del parachoques de luz central izquierdo</translation>
    </message>
    <message>
        <source>Light Bump Center Right Signal</source>
        <translation>Señal del parachoques de luz central derecho</translation>
    </message>
    <message>
        <source>Light Bump Front Left Signal</source>
        <translation>Señal del parachoques de luz delantero izquierdo</translation>
    </message>
    <message>
        <source>Light Bump Front Right Signal</source>
        <translation>Señal del parachoques de luz delantero derecho</translation>
    </message>
    <message>
        <source>Light Bump Left Signal</source>
        <translation>Señal del parachoques de luz izquierdo</translation>
    </message>
    <message>
        <source>Light Bump Right Signal</source>
        <translation>Señal del parachoques de luz derecho</translation>
    </message>
    <message>
        <source>Light Bumper</source>
        <translation>Parachoques de luz</translation>
    </message>
    <message>
        <source>Main Brush Motor Current</source>
        <translation>Corriente del motor del cepillo principal</translation>
    </message>
    <message>
        <source>Number of Stream Packets</source>
        <translation>Número de paquetes del flujo de datos</translation>
    </message>
    <message>
        <source>OI Mode</source>
        <translation>Modo OI</translation>
    </message>
    <message>
        <source>Overcurrents</source>
        <translation>Sobrecorrientes</translation>
    </message>
    <message>
        <source>Requested Left Velocity</source>
        <translation>Velocidad izquierda solicitada</translation>
    </message>
    <message>
        <source>Requested Radius</source>
        <translation>Radio solicitado</translation>
    </message>
    <message>
        <source>Requested Right Velocity</source>
        <translation>Velocidad derecha solicitada</translation>
    </message>
    <message>
        <source>Requested Velocity</source>
        <translation>Velocidad solicitada</translation>
    </message>
    <message>
        <source>Right Encoder Counts</source>
        <translation>Cuentas del codificador derecho</translation>
    </message>
    <message>
        <source>Right Motor Current</source>
        <translation>Corriente del motor derecho</translation>
    </message>
    <message>
        <source>Side Brush Motor Current</source>
        <translation>Corriente del motor del cepillo lateral</translation>
    </message>
    <message>
        <source>Song Number</source>
        <translation>Número de canción</translation>
    </message>
    <message>
        <source>Song Playing</source>
        <translation>Canción en reproducción</translation>
    </message>
    <message>
        <source>Stasis</source>
        <translation>Estasis</translation>
    </message>
    <message>
        <source>Temperature</source>
        <translation>Temperatura</translation>
    </message>
    <message>
        <source>Unused</source>
        <translation>Sin uso</translation>
    </message>
    <message>
        <source>Virtual Wall</source>
        <translation>Pared virtual</translation>
    </message>
    <message>
        <source>Voltage</source>
        <translation>Tensión</translation>
    </message>
    <message>
        <source>Wall</source>
        <translation>Pared</translation>
    </message>
    <message>
        <source>Wall Signal</source>
        <translation>Señal de pared</translation>
    </message>
    <message>
        <source>Infrared Character Omni</source>
        <translation>Carácter infrarrojo omnidireccional</translation>
    </message>
    <message>
        <source>Infrared Byte</source>
        <translation>Byte infrarrojo</translation>
    </message>
</context>
<context>
    <name>PacketTable</name>
    <message>
        <source>Packets</source>
        <translation>Paquetes</translation>
    </message>
    <message>
        <source>Plot</source>
        <translation>Graficar</translation>
    </message>
    <message>
        <source>Plot the chosen packet (or double-click its row)</source>
        <translation>Graficar el paquete elegido (o hacer doble clic en su fila)</translation>
    </message>
</context>
<context>
    <name>PacketTableModel</name>
    <message>
        <source>Id</source>
        <translation>Id</translation>
    </message>
    <message>
        <source>Packet</source>
        <translation>Paquete</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Valor</translation>
    </message>
    <message>
        <source>Raw</source>
        <translation>Bruto</translation>
    </message>
    <message>
        <source>Rate</source>
        <translation>Frecuencia</translation>
    </message>
</context>
<context>
    <name>PianoRoll</name>
    <message>
        <source>rest</source>
        <translation>silencio</translation>
    </message>
    <message>
        <source>Click to add a note, drag a note to move it, drag its right edge to lengthen it</source>
        <translation>Haga clic para añadir una nota, arrastre una nota para moverla, arrastre su borde derecho para alargarla</translation>
    </message>
    <message>
        <source>Piano roll</source>
        <translation>Rollo de piano</translation>
    </message>
    <message>
        <source>1 note, %1 s.</source>
        <translation>1 nota, %1 s.</translation>
    </message>
    <message numerus="yes">
        <source>%n notes, %1 s.</source>
        <translation>
            <numerusform>%n nota, %1 s.</numerusform>
            <numerusform>%n notas, %1 s.</numerusform>
        </translation>
    </message>
    <message>
        <source>Selected: note %1, %2, %3/64 s.</source>
        <translation>Seleccionada: nota %1, %2, %3/64 s.</translation>
    </message>
    <message>
        <source>Left and Right select a note, Up and Down change its pitch, Shift+Left and Shift+Right its length, Insert adds a note, Delete removes one.</source>
        <translation>Izquierda y Derecha seleccionan una nota, Arriba y Abajo cambian su tono, Mayús+Izquierda y Mayús+Derecha su duración, Insert añade una nota y Supr la elimina.</translation>
    </message>
    <message>
        <source>A song holds at most %1 notes; remove one first</source>
        <translation>Una canción admite como máximo %1 notas; elimine una primero</translation>
    </message>
</context>
<context>
    <name>PlotStack</name>
    <message>
        <source>Remove this plot</source>
        <translation>Quitar esta gráfica</translation>
    </message>
    <message>
        <source>Sensor plot</source>
        <translation>Gráfica de sensores</translation>
    </message>
    <message>
        <source>Choose the channels to plot with the button above</source>
        <translation>Elija los canales que desea representar con el botón de arriba</translation>
    </message>
    <message>
        <source>No samples in this time range</source>
        <translation>No hay muestras en este intervalo de tiempo</translation>
    </message>
    <message>
        <source>Waiting for samples</source>
        <translation>Esperando muestras</translation>
    </message>
    <message>
        <source>%1 (unreliable)</source>
        <translation>%1 (no fiable)</translation>
    </message>
    <message>
        <source>%1 (moved %2 s)</source>
        <translation>%1 (desplazado %2 s)</translation>
    </message>
    <message>
        <source>No channels chosen</source>
        <translation>Ningún canal elegido</translation>
    </message>
    <message>
        <source>Channels: %1</source>
        <translation>Canales: %1</translation>
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
        <translation>Tiempo (s)</translation>
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
        <translation>Vista de &amp;proyector</translation>
    </message>
    <message>
        <source>Large type, high contrast, the selected robot or the lesson alone (F11)</source>
        <translation>Letra grande, alto contraste, solo el robot seleccionado o la lección (F11)</translation>
    </message>
</context>
<context>
    <name>ProjectorView</name>
    <message>
        <source>battery %1 %</source>
        <translation>batería %1 %</translation>
    </message>
    <message>
        <source>NO LIVE DATA</source>
        <translation>SIN DATOS EN VIVO</translation>
    </message>
    <message>
        <source>lesson complete</source>
        <translation>lección completada</translation>
    </message>
    <message>
        <source>F11: leave the projector view · Esc: stop the robot and leave</source>
        <translation>F11: salir de la vista de proyector · Esc: detener el robot y salir</translation>
    </message>
    <message>
        <source>Projector view</source>
        <translation>Vista de proyector</translation>
    </message>
    <message>
        <source>Enter Safe (Enter)</source>
        <translation>Pasar a Safe (Intro)</translation>
    </message>
    <message>
        <source>This step expects it: follow the step below.</source>
        <translation>Este paso lo espera: sigue el paso de abajo.</translation>
    </message>
</context>
<context>
    <name>Recording</name>
    <message>
        <source>cannot create the recording</source>
        <translation>no se puede crear la grabación</translation>
    </message>
    <message>
        <source>cannot write</source>
        <translation>no se puede escribir</translation>
    </message>
    <message>
        <source>%1 at byte %2 (record %3, after %4 s)</source>
        <translation>%1 en el byte %2 (registro %3, tras %4 s)</translation>
    </message>
    <message>
        <source>not a Roomba Dashboard recording</source>
        <translation>no es una grabación de Roomba Dashboard</translation>
    </message>
    <message>
        <source>the header is truncated</source>
        <translation>la cabecera está truncada</translation>
    </message>
    <message>
        <source>the header is not valid JSON: %1</source>
        <translation>la cabecera no es JSON válido: %1</translation>
    </message>
    <message>
        <source>truncated record</source>
        <translation>registro truncado</translation>
    </message>
    <message>
        <source>checksum mismatch</source>
        <translation>suma de comprobación incorrecta</translation>
    </message>
    <message>
        <source>time runs backwards</source>
        <translation>el tiempo retrocede</translation>
    </message>
    <message>
        <source>unreadable stream description</source>
        <translation>descripción del flujo de datos ilegible</translation>
    </message>
    <message>
        <source>unknown record type 0x%1</source>
        <translation>tipo de registro desconocido 0x%1</translation>
    </message>
    <message>
        <source>damaged before the stream started: %1</source>
        <translation>dañada antes de que empezara el flujo de datos: %1</translation>
    </message>
    <message>
        <source>the recording holds no sensor stream</source>
        <translation>la grabación no contiene ningún flujo de sensores</translation>
    </message>
    <message>
        <source>recording format version %1; this program reads versions %2 to %3</source>
        <translation>formato de grabación versión %1; este programa lee las versiones %2 a %3</translation>
    </message>
    <message>
        <source>unreadable marker</source>
        <translation>marca ilegible</translation>
    </message>
    <message>
        <source>unreadable true pose</source>
        <translation>pose real ilegible</translation>
    </message>
    <message>
        <source>packet %1 is in it twice</source>
        <translation>el paquete %1 aparece dos veces</translation>
    </message>
    <message>
        <source>a stream no robot sends (%1)</source>
        <translation>un flujo de datos que ningún robot envía (%1)</translation>
    </message>
</context>
<context>
    <name>RecordingActions</name>
    <message>
        <source>&amp;Record</source>
        <translation>&amp;Grabar</translation>
    </message>
    <message>
        <source>Record every byte to and from the selected robot into a file</source>
        <translation>Graba en un archivo cada byte enviado al robot seleccionado y recibido de él</translation>
    </message>
    <message>
        <source>&amp;Open recording…</source>
        <translation>A&amp;brir grabación…</translation>
    </message>
    <message>
        <source>Replay a recording as a robot of its own</source>
        <translation>Reproduce una grabación como un robot más</translation>
    </message>
    <message>
        <source>&amp;Export recording as CSV…</source>
        <translation>&amp;Exportar grabación como CSV…</translation>
    </message>
    <message>
        <source>Record %1 to</source>
        <translation>Grabar %1 en</translation>
    </message>
    <message>
        <source>Roomba Dashboard recordings (*.oirec)</source>
        <translation>Grabaciones de Roomba Dashboard (*.oirec)</translation>
    </message>
    <message>
        <source>Open recording</source>
        <translation>Abrir grabación</translation>
    </message>
    <message>
        <source>Roomba Dashboard recordings (*.oirec);;All files (*)</source>
        <translation>Grabaciones de Roomba Dashboard (*.oirec);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>This file cannot be replayed.

%1</source>
        <translation>Este archivo no se puede reproducir.

%1</translation>
    </message>
    <message>
        <source>Export recording as CSV</source>
        <translation>Exportar grabación como CSV</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>Archivos CSV (*.csv)</translation>
    </message>
    <message>
        <source>Nothing was written.

%1</source>
        <translation>No se escribió nada.

%1</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>Se escribió %1</translation>
    </message>
    <message>
        <source>Recording and replay</source>
        <translation>Grabación y reproducción</translation>
    </message>
    <message>
        <source>Export recording as &amp;MCAP…</source>
        <translation>Exportar grabación como &amp;MCAP…</translation>
    </message>
    <message>
        <source>For Foxglove, Lichtblick and PlotJuggler</source>
        <translation>Para Foxglove, Lichtblick y PlotJuggler</translation>
    </message>
    <message>
        <source>MCAP, zstd compression (*.mcap)</source>
        <translation>MCAP, compresión zstd (*.mcap)</translation>
    </message>
    <message>
        <source>MCAP, lz4 compression: quicker to open (*.mcap)</source>
        <translation>MCAP, compresión lz4: se abre más rápido (*.mcap)</translation>
    </message>
    <message>
        <source>Export recording as MCAP</source>
        <translation>Exportar grabación como MCAP</translation>
    </message>
    <message>
        <source>The recording is damaged; %1 holds everything up to the damage.

%2</source>
        <translation>La grabación está dañada; %1 contiene todo hasta el daño.

%2</translation>
    </message>
    <message>
        <source>Replay</source>
        <translation>Reproducción</translation>
    </message>
    <message>
        <source>Export another recording as CSV…</source>
        <translation>Exportar otra grabación como CSV…</translation>
    </message>
    <message>
        <source>Export another recording as MCAP…</source>
        <translation>Exportar otra grabación como MCAP…</translation>
    </message>
    <message>
        <source>The recording on screen: a replay, or the last recording of the selected robot</source>
        <translation>La grabación en pantalla: una reproducción, o la última grabación del robot elegido</translation>
    </message>
    <message>
        <source>Choose a recording file first, then where to write the CSV</source>
        <translation>Elige primero un archivo de grabación, luego dónde escribir el CSV</translation>
    </message>
    <message>
        <source>Choose a recording file first, then where to write the MCAP file</source>
        <translation>Elige primero un archivo de grabación, luego dónde escribir el archivo MCAP</translation>
    </message>
    <message>
        <source>Choose the recording to export as %1</source>
        <translation>Elige la grabación que se exporta como %1</translation>
    </message>
    <message>
        <source>Export %1 as %2</source>
        <translation>Exportar %1 como %2</translation>
    </message>
</context>
<context>
    <name>RecordingMarkers</name>
    <message>
        <source>%1 markers beyond the first %2 were left out: a recording holds at most %2</source>
        <translation>se omitieron %1 marcas después de las primeras %2: una grabación admite como máximo %2</translation>
    </message>
</context>
<context>
    <name>RemoteRobot</name>
    <message>
        <source>state: &quot;%1&quot; must be a string</source>
        <translation>estado: «%1» debe ser una cadena</translation>
    </message>
    <message>
        <source>state: &quot;online&quot; must be true or false</source>
        <translation>estado: «online» debe ser true o false</translation>
    </message>
    <message>
        <source>state: &quot;battery_percent&quot; must be a number</source>
        <translation>estado: «battery_percent» debe ser un número</translation>
    </message>
    <message>
        <source>state: &quot;mode_cause&quot; must be a list of words</source>
        <translation>estado: «mode_cause» debe ser una lista de palabras</translation>
    </message>
    <message>
        <source>state: &quot;battery&quot; must be an object</source>
        <translation>estado: «battery» debe ser un objeto</translation>
    </message>
</context>
<context>
    <name>ReplayBar</name>
    <message>
        <source>One frame back</source>
        <translation>Una trama atrás</translation>
    </message>
    <message>
        <source>One frame forward</source>
        <translation>Una trama adelante</translation>
    </message>
    <message>
        <source>Replay speed</source>
        <translation>Velocidad de reproducción</translation>
    </message>
    <message>
        <source>Position in the recording</source>
        <translation>Posición en la grabación</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pausa</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Reproducir</translation>
    </message>
    <message>
        <source>%1 / %2, frame %3 of %4</source>
        <translation>%1 / %2, trama %3 de %4</translation>
    </message>
    <message>
        <source>Damaged: replays up to %1</source>
        <translation>Dañada: se reproduce hasta %1</translation>
    </message>
    <message>
        <source>Previous marker (,)</source>
        <translation>Marca anterior (,)</translation>
    </message>
    <message>
        <source>Previous marker</source>
        <translation>Marca anterior</translation>
    </message>
    <message>
        <source>Next marker (.)</source>
        <translation>Marca siguiente (.)</translation>
    </message>
    <message>
        <source>Next marker</source>
        <translation>Marca siguiente</translation>
    </message>
</context>
<context>
    <name>RobotAddress</name>
    <message>
        <source>&apos;%1&apos; is not HOST:PORT with a port from 1 to 65535, e.g. raspberrypi:3333</source>
        <translation>«%1» no es HOST:PUERTO con un puerto de 1 a 65535, p. ej. raspberrypi:3333</translation>
    </message>
    <message>
        <source>give only one of --sim, --port and --tcp</source>
        <translation>indique solo uno de --sim, --port y --tcp</translation>
    </message>
    <message>
        <source>give the serial port&apos;s path, e.g. /dev/ttyUSB0</source>
        <translation>indique la ruta del puerto serie, p. ej. /dev/ttyUSB0</translation>
    </message>
    <message>
        <source>unknown profile &apos;%1&apos; (roomba500, create2, create1 or auto)</source>
        <translation>perfil desconocido «%1» (roomba500, create2, create1 o auto)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a rate the robots know (300 to 115200)</source>
        <translation>«%1» no es una velocidad que los robots conozcan (300 a 115200)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not an option for where the robot is</source>
        <translation>«%1» no es una opción sobre dónde está el robot</translation>
    </message>
    <message>
        <source>--profile, --baud and --brc-line go with --sim, --port or --tcp</source>
        <translation>--profile, --baud y --brc-line van con --sim, --port o --tcp</translation>
    </message>
    <message>
        <source>say where the robot is: --sim, --port PATH or --tcp HOST:PORT</source>
        <translation>indique dónde está el robot: --sim, --port RUTA o --tcp HOST:PUERTO</translation>
    </message>
</context>
<context>
    <name>RobotBar</name>
    <message>
        <source>Robots</source>
        <translation>Robots</translation>
    </message>
    <message>
        <source>Recording of %1</source>
        <translation>Grabación de un %1</translation>
    </message>
    <message>
        <source>&amp;Stop all robots	Shift+Esc</source>
        <translation>&amp;Detener todos los robots	Mayús+Esc</translation>
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
        <translation>Robot %1</translation>
    </message>
    <message>
        <source>%1, link %2</source>
        <translation>%1, enlace %2</translation>
    </message>
    <message>
        <source>%1
%2
Link: %3
Double-click to rename</source>
        <translation>%1
%2
Enlace: %3
Doble clic para renombrar</translation>
    </message>
</context>
<context>
    <name>RobotDiagram</name>
    <message>
        <source>Robot sensor diagram</source>
        <translation>Diagrama de sensores del robot</translation>
    </message>
    <message>
        <source>Data is stale</source>
        <translation>Los datos están obsoletos</translation>
    </message>
    <message>
        <source>Bump left</source>
        <translation>Parachoques izquierdo</translation>
    </message>
    <message>
        <source>Bump right</source>
        <translation>Parachoques derecho</translation>
    </message>
    <message>
        <source>Wheel drop left</source>
        <translation>Caída de rueda izquierda</translation>
    </message>
    <message>
        <source>Wheel drop right</source>
        <translation>Caída de rueda derecha</translation>
    </message>
    <message>
        <source>Caster wheel drop</source>
        <translation>Caída de rueda loca</translation>
    </message>
    <message>
        <source>Cliff left</source>
        <translation>Desnivel izquierdo</translation>
    </message>
    <message>
        <source>Cliff front left</source>
        <translation>Desnivel delantero izquierdo</translation>
    </message>
    <message>
        <source>Cliff front right</source>
        <translation>Desnivel delantero derecho</translation>
    </message>
    <message>
        <source>Cliff right</source>
        <translation>Desnivel derecho</translation>
    </message>
    <message>
        <source>Wall</source>
        <translation>Pared</translation>
    </message>
    <message>
        <source>Light bumper %1</source>
        <translation>Parachoques de luz %1</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>No sensor data</source>
        <translation>Sin datos de sensores</translation>
    </message>
    <message>
        <source>Nothing detected</source>
        <translation>Nada detectado</translation>
    </message>
    <message>
        <source>; </source>
        <translation>; </translation>
    </message>
    <message>
        <source>Buttons</source>
        <translation>Botones</translation>
    </message>
    <message>
        <source>none</source>
        <translation>ninguno</translation>
    </message>
    <message>
        <source>Virtual wall</source>
        <translation>Pared virtual</translation>
    </message>
    <message>
        <source>seen</source>
        <translation>detectada</translation>
    </message>
    <message>
        <source>Overcurrent</source>
        <translation>Sobrecorriente</translation>
    </message>
    <message>
        <source>IR</source>
        <translation>IR</translation>
    </message>
    <message>
        <source>Stasis</source>
        <translation>Estasis</translation>
    </message>
    <message>
        <source>not moving</source>
        <translation>sin movimiento</translation>
    </message>
    <message>
        <source>moving</source>
        <translation>en movimiento</translation>
    </message>
    <message>
        <source>DIRTY WHEEL</source>
        <translation>RUEDA SUCIA</translation>
    </message>
    <message>
        <source>reserved (3)</source>
        <translation>reservado (3)</translation>
    </message>
    <message>
        <source>IR omni</source>
        <translation>IR omni</translation>
    </message>
    <message>
        <source>IR left</source>
        <translation>IR izquierdo</translation>
    </message>
    <message>
        <source>IR right</source>
        <translation>IR derecho</translation>
    </message>
    <message>
        <source>CARGO BAY</source>
        <translation>BAHÍA DE CARGA</translation>
    </message>
    <message>
        <source>DROP</source>
        <translation>CAÍDA</translation>
    </message>
    <message>
        <source>WALL</source>
        <translation>PARED</translation>
    </message>
    <message>
        <source>STALE</source>
        <translation>OBSOLETO</translation>
    </message>
    <message>
        <source>The replay has ended</source>
        <translation>La reproducción ha terminado</translation>
    </message>
    <message>
        <source>ENDED</source>
        <translation>TERMINADA</translation>
    </message>
</context>
<context>
    <name>RobotFirmware</name>
    <message>
        <source>The robot printed no firmware version within %1 s of Reset. Check that it is switched on and connected, and try again once it streams.</source>
        <translation>El robot no imprimió ninguna versión de firmware en los %1 s siguientes al Reset. Compruebe que está encendido y conectado, y vuelva a intentarlo cuando envíe datos.</translation>
    </message>
    <message>
        <source>The firmware version is not known: values are shown as the robot reports them.</source>
        <translation>No se conoce la versión del firmware: los valores se muestran tal como los da el robot.</translation>
    </message>
    <message>
        <source>This firmware reports distance, angle and radius correctly: nothing needs correcting.</source>
        <translation>Este firmware informa bien de la distancia, el ángulo y el radio: no hay nada que corregir.</translation>
    </message>
    <message>
        <source>It reports the angle (packet 20) multiplied by %1: the angle is divided by %1 wherever it is shown, plotted, exported or used for the map.</source>
        <translation>Informa del ángulo (paquete 20) multiplicado por %1: el ángulo se divide entre %1 allí donde se muestra, se grafica, se exporta o se usa para el mapa.</translation>
    </message>
    <message>
        <source>It reports the distance (packet 19) and the requested radius (packet 40) wrongly: they are greyed, and the map uses the wheel encoders.</source>
        <translation>Informa mal de la distancia (paquete 19) y del radio pedido (paquete 40): se muestran en gris y el mapa usa los codificadores de las ruedas.</translation>
    </message>
    <message>
        <source>This robot reports its mode (packet 35) one too high (Passive as 2, Safe as 3, Full as 4): the true mode is shown and used everywhere.</source>
        <translation>Este robot informa su modo (paquete 35) uno más alto (Passive como 2, Safe como 3, Full como 4): en todas partes se muestra y se usa el modo real.</translation>
    </message>
</context>
<context>
    <name>RobotFleet</name>
    <message>
        <source>Robot</source>
        <translation>Robot</translation>
    </message>
</context>
<context>
    <name>RobotLink</name>
    <message>
        <source>%1: no transport for this kind of connection</source>
        <translation>%1: no hay transporte para este tipo de conexión</translation>
    </message>
    <message>
        <source>%1: the connection ended during the check</source>
        <translation>%1: la conexión terminó durante la comprobación</translation>
    </message>
    <message>
        <source>%1: switched off at its power button; press it or use Wake (roomba-ctl wake, or Connect again in the dashboard). The link streams again once it is on.</source>
        <translation>%1: apagado con su botón de encendido; púlselo o use «Despertar» (roomba-ctl wake, o «Conectar» de nuevo en el panel). El enlace vuelve a transmitir cuando esté encendido.</translation>
    </message>
    <message>
        <source>%1: the robot stopped sending and does not answer Start: is it still switched on, is its battery charged, and is the cable in?</source>
        <translation>%1: el robot dejó de enviar y no responde a Start: ¿sigue encendido, tiene la batería cargada y está el cable conectado?</translation>
    </message>
    <message>
        <source>%1: the robot stopped sending: it is probably asleep (a %2 sleeps after 5 minutes in Passive), and no pulse can wake it here: %3. Press Clean to wake it; the link streams again once it is awake. To wake it from here, wire its BRC pin to the adapter&apos;s RTS or DTR line and set that wake line.</source>
        <translation>%1: el robot dejó de enviar: probablemente duerme (un %2 se duerme tras 5 minutos en Passive), y aquí ningún pulso puede despertarlo: %3. Pulse Clean para despertarlo; el enlace vuelve a transmitir cuando esté despierto. Para despertarlo desde aquí, conecte su pin BRC a la línea RTS o DTR del adaptador y elija esa línea de despertar.</translation>
    </message>
    <message>
        <source>the port is closed</source>
        <translation>el puerto está cerrado</translation>
    </message>
    <message>
        <source>%1: the robot is asleep on its dock, and a BRC pulse did not wake it: firmware older than release-3.8.2 (release-stm32-3.7.7) is not woken by a pulse on the dock. Press Clean or lift it off the dock; the link streams again once it is awake.</source>
        <translation>%1: el robot duerme en su base y un pulso BRC no lo despertó: un firmware anterior a release-3.8.2 (release-stm32-3.7.7) no despierta por un pulso en la base. Pulse Clean o levántelo de la base; el enlace vuelve a transmitir cuando esté despierto.</translation>
    </message>
    <message>
        <source>%1: the robot stopped sending and did not wake when its wake line (%2) was pulsed: it is asleep and the pulse does not reach it. The cable may carry the BRC pin on the other line (set the wake line to DTR, RTS or both; the connection check tries each) or not at all. On its dock, firmware older than release-3.8.2 is not woken by a pulse: press Clean or lift it off the dock; the link streams again once it is awake.</source>
        <translation>%1: el robot dejó de enviar y no despertó al pulsar su línea de despertar (%2): duerme y el pulso no le llega. Puede que el cable lleve el pin BRC en la otra línea (ponga la línea de despertar en DTR, RTS o ambas; la comprobación de conexión prueba cada una) o que no lo lleve. En su base, un firmware anterior a release-3.8.2 no despierta por un pulso: pulse Clean o levántelo de la base; el enlace vuelve a transmitir cuando esté despierto.</translation>
    </message>
    <message>
        <source>%1: no data: is the robot on, and is the baud right?</source>
        <translation>%1: sin datos: ¿está encendido el robot y es correcta la velocidad en baudios?</translation>
    </message>
    <message>
        <source>(If it is asleep: %1.)</source>
        <translation>(Si está dormido: %1.)</translation>
    </message>
    <message>
        <source>no packet fits in a 15 ms frame at %1 baud</source>
        <translation>ningún paquete cabe en una trama de 15 ms a %1 baudios</translation>
    </message>
    <message>
        <source>%1: cannot stream: %2</source>
        <translation>%1: no se puede transmitir: %2</translation>
    </message>
    <message>
        <source>not connected: the command was not sent</source>
        <translation>sin conexión: la orden no se envió</translation>
    </message>
    <message>
        <source>the connection check is running: the command was not sent</source>
        <translation>la comprobación de la conexión está en curso: no se envió la orden</translation>
    </message>
    <message>
        <source>%1: Reset put the robot back at its default %2 baud, which this connection cannot follow from %3: %4</source>
        <translation>%1: Reset devolvió el robot a su velocidad por defecto de %2 baudios, que esta conexión no puede seguir desde %3: %4</translation>
    </message>
    <message>
        <source>%1: Reset put the robot back at its default %2 baud: the port now talks at %2 too (it was %3).</source>
        <translation>%1: Reset devolvió el robot a su velocidad por defecto de %2 baudios: el puerto ahora también habla a %2 (antes, a %3).</translation>
    </message>
    <message>
        <source>Not sent: %1</source>
        <translation>No enviado: %1</translation>
    </message>
    <message>
        <source>%1: write failed</source>
        <translation>%1: error de escritura</translation>
    </message>
    <message>
        <source>not connected: the sensor query was not sent</source>
        <translation>sin conexión: la consulta de sensores no se envió</translation>
    </message>
    <message>
        <source>sensor query: %1 is not a packet or group of the %2</source>
        <translation>consulta de sensores: %1 no es un paquete ni un grupo del %2</translation>
    </message>
    <message>
        <source>sensor query: ask for 1 to 255 packets</source>
        <translation>consulta de sensores: pida de 1 a 255 paquetes</translation>
    </message>
    <message>
        <source>sensor query: the %1 has no Query List; ask for one group at a time (0 is every packet)</source>
        <translation>consulta de sensores: el %1 no tiene Query List; pida un grupo cada vez (0 son todos los paquetes)</translation>
    </message>
    <message>
        <source>not connected: Show Script was not sent</source>
        <translation>sin conexión: Show Script no se envió</translation>
    </message>
    <message>
        <source>the %1 has no scripts</source>
        <translation>el %1 no tiene scripts</translation>
    </message>
    <message>
        <source>%1: the stream did not pause; the sensor query was not sent</source>
        <translation>%1: el flujo de datos no se pausó; la consulta de sensores no se envió</translation>
    </message>
    <message>
        <source>%1: no reply to Show Script</source>
        <translation>%1: sin respuesta a Show Script</translation>
    </message>
    <message>
        <source>%1: no reply to the sensor query</source>
        <translation>%1: sin respuesta a la consulta de sensores</translation>
    </message>
    <message>
        <source>not connected: there is nothing to wake</source>
        <translation>sin conexión: no hay nada que despertar</translation>
    </message>
    <message>
        <source>%1: no pulse can wake the robot here: %2. Press its power button (Clean).</source>
        <translation>%1: aquí ningún pulso puede despertar al robot: %2. Pulse su botón de encendido (Clean).</translation>
    </message>
    <message>
        <source>not connected: there is nothing to check</source>
        <translation>sin conexión: no hay nada que comprobar</translation>
    </message>
    <message>
        <source>%1: the port is not open yet</source>
        <translation>%1: el puerto aún no está abierto</translation>
    </message>
</context>
<context>
    <name>RobotList</name>
    <message>
        <source>Add robot</source>
        <translation>Añadir robot</translation>
    </message>
    <message>
        <source>Add a robot to the window: a virtual one, a serial port or TCP bridge, or a recording</source>
        <translation>Añade un robot a la ventana: uno virtual, un puerto serie o puente TCP, o una grabación</translation>
    </message>
    <message>
        <source>Virtual robot</source>
        <translation>Robot virtual</translation>
    </message>
    <message>
        <source>Serial port or TCP bridge…</source>
        <translation>Puerto serie o puente TCP…</translation>
    </message>
    <message>
        <source>Recording…</source>
        <translation>Grabación…</translation>
    </message>
    <message>
        <source>Rename</source>
        <translation>Renombrar</translation>
    </message>
    <message>
        <source>Rename the selected robot (or double-click its card)</source>
        <translation>Renombra el robot seleccionado (o haz doble clic en su tarjeta)</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Quitar</translation>
    </message>
    <message>
        <source>Stop the selected robot, leave it in Passive and remove it from the window</source>
        <translation>Detiene el robot seleccionado, lo deja en Pasivo y lo quita de la ventana</translation>
    </message>
    <message>
        <source>Robot name</source>
        <translation>Nombre del robot</translation>
    </message>
</context>
<context>
    <name>RobotMarkers</name>
    <message>
        <source>Markers are kept in a recording: start one (File → Record) or open one.</source>
        <translation>Las marcas se guardan en una grabación: inicie una (Archivo → Grabar) o abra una.</translation>
    </message>
    <message>
        <source>There is no marker %1.</source>
        <translation>No hay ninguna marca %1.</translation>
    </message>
    <message>
        <source>The marker could not be saved: %1</source>
        <translation>No se pudo guardar la marca: %1</translation>
    </message>
    <message>
        <source>A recording holds at most %1 markers.</source>
        <translation>Una grabación admite como máximo %1 marcas.</translation>
    </message>
</context>
<context>
    <name>RobotMode</name>
    <message>
        <source>left</source>
        <translation>izquierdo</translation>
    </message>
    <message>
        <source>front left</source>
        <translation>delantero izquierdo</translation>
    </message>
    <message>
        <source>front right</source>
        <translation>delantero derecho</translation>
    </message>
    <message>
        <source>right</source>
        <translation>derecho</translation>
    </message>
    <message>
        <source>cliff (%1)</source>
        <translation>desnivel (%1)</translation>
    </message>
    <message>
        <source>, </source>
        <translation>, </translation>
    </message>
    <message>
        <source>caster</source>
        <translation>rueda loca</translation>
    </message>
    <message>
        <source>wheel drop (%1)</source>
        <translation>rueda caída (%1)</translation>
    </message>
    <message>
        <source>charger</source>
        <translation>cargador</translation>
    </message>
    <message>
        <source> and </source>
        <translation> y </translation>
    </message>
    <message>
        <source>You asked for Passive at %1.</source>
        <translation>A las %1 pidió el modo Passive.</translation>
    </message>
    <message>
        <source>A safety stop dropped it to Passive at %1.</source>
        <translation>A las %1 una parada de seguridad lo pasó a Passive.</translation>
    </message>
    <message>
        <source>A %1 dropped it to Passive at %2.</source>
        <translation>A las %2 pasó a Passive por: %1.</translation>
    </message>
    <message>
        <source>asked for</source>
        <translation>pedido</translation>
    </message>
    <message>
        <source>safety stop</source>
        <translation>parada de seguridad</translation>
    </message>
    <message>
        <source>Carry it back from the edge, then Enter Safe.</source>
        <translation>Apártelo del borde y pase a Safe.</translation>
    </message>
    <message>
        <source>Put it back on its wheels, then Enter Safe.</source>
        <translation>Póngalo de nuevo sobre sus ruedas y pase a Safe.</translation>
    </message>
    <message>
        <source>Enter Safe to drive.</source>
        <translation>Pase a Safe para conducir.</translation>
    </message>
    <message>
        <source>%1 needs Safe or Full mode: in Passive the Create ignores the script&apos;s Drive, so a wait never ends. Enter Safe first.</source>
        <translation>%1 necesita el modo Safe o Full: en Passive el Create ignora el Drive del guion, así que una espera no termina nunca. Pase antes a Safe.</translation>
    </message>
    <message>
        <source>%1 needs Safe or Full mode: the robot ignores it in Passive. Enter Safe first.</source>
        <translation>%1 necesita el modo Safe o Full: en Passive el robot lo ignora. Pase antes a Safe.</translation>
    </message>
    <message>
        <source>Out of reach: %1 The goal needs the %2 cliff sensor to reach the edge first. Carry the robot back from the edge, Enter Safe, and drive at the edge head on.</source>
        <translation>Fuera de alcance: %1 El objetivo necesita que el sensor de desnivel %2 llegue antes al borde. Aparte el robot del borde, pase a Safe y avance de frente hacia el borde.</translation>
    </message>
    <message>
        <source> or </source>
        <translation> o </translation>
    </message>
    <message>
        <source>Out of reach: the robot does not drive in Passive mode. %1</source>
        <translation>Fuera de alcance: en modo Passive el robot no conduce. %1</translation>
    </message>
    <message>
        <source>on the dock, not charging</source>
        <translation>en la base, sin cargar</translation>
    </message>
    <message>
        <source>Full mode on the dock: the battery does not charge, it drains.</source>
        <translation>Modo Full en la base: la batería no carga, se descarga.</translation>
    </message>
    <message>
        <source>Safe mode on the dock: the battery does not charge, it drains.</source>
        <translation>Modo Safe en la base: la batería no carga, se descarga.</translation>
    </message>
    <message>
        <source>The robot is on its dock: Safe mode is refused on the charger (%1).</source>
        <translation>El robot está en su base: en el cargador se rechaza el modo Safe (%1).</translation>
    </message>
    <message>
        <source>Safe refused on the dock</source>
        <translation>Safe rechazado en la base</translation>
    </message>
    <message>
        <source>Enter Passive to charge it, or drive it off the dock.</source>
        <translation>Entra en Passive para cargarlo, o sácalo de la base conduciendo.</translation>
    </message>
    <message>
        <source>Lift it off the dock, or drive it off in Full (Full does not stop at cliffs or wheel drops).</source>
        <translation>Levántelo de la base, o sáquelo conduciendo en Full (Full no se detiene ante desniveles ni ruedas caídas).</translation>
    </message>
    <message>
        <source>Carry it back from the edge, then Enter Safe. Its cliff signals read %1 of 4095, as over a dark rug: if you can see the floor under it, carry it to a lighter floor, then Enter Safe.</source>
        <translation>Apártelo del borde y pase a Safe. Sus señales de desnivel leen %1 de 4095, como sobre una alfombra oscura: si ve el suelo debajo, llévelo a un suelo más claro y pase a Safe.</translation>
    </message>
    <message>
        <source>Cleaning (its own program) · Space stops it</source>
        <translation>Limpiando (su propio programa) · Espacio lo detiene</translation>
    </message>
    <message>
        <source>Seeking its dock (its own program) · Space stops it</source>
        <translation>Buscando su base (su propio programa) · Espacio lo detiene</translation>
    </message>
    <message>
        <source>Running a demo (its own program) · Space stops it</source>
        <translation>Ejecutando una demo (su propio programa) · Espacio lo detiene</translation>
    </message>
    <message>
        <source>cleaning</source>
        <translation>limpiando</translation>
    </message>
    <message>
        <source>seeking its dock</source>
        <translation>buscando su base</translation>
    </message>
    <message>
        <source>running a demo</source>
        <translation>ejecutando una demo</translation>
    </message>
    <message>
        <source>the robot is off the floor: Full mode would drive its wheels in your hands</source>
        <translation>el robot no está en el suelo: en modo Full sus ruedas girarían mientras lo sostiene</translation>
    </message>
    <message>
        <source>battery nearly flat</source>
        <translation>batería casi agotada</translation>
    </message>
    <message>
        <source>%1 (it fell to Passive at %2).</source>
        <translation>%1 (pasó a Passive a las %2).</translation>
    </message>
    <message>
        <source>Put it on its dock in Passive to charge it; it drives again once charged.</source>
        <translation>Póngalo en su base en Passive para cargarlo; volverá a conducir cuando esté cargado.</translation>
    </message>
</context>
<context>
    <name>RobotSession</name>
    <message>
        <source>Connect to the robot first: its firmware version is read from the robot.</source>
        <translation>Conéctese primero al robot: la versión del firmware se lee del robot.</translation>
    </message>
    <message>
        <source>A recording cannot be reset: connect to the robot itself to read its firmware version.</source>
        <translation>Una grabación no se puede reiniciar: conéctese al propio robot para leer la versión de su firmware.</translation>
    </message>
    <message>
        <source>A robot on the broker is reset only by its bridge: read its firmware version where the bridge runs.</source>
        <translation>Un robot en el bróker solo lo reinicia su puente: lea la versión de su firmware donde se ejecuta el puente.</translation>
    </message>
    <message>
        <source>Not sent: %1</source>
        <translation>No enviado: %1</translation>
    </message>
    <message>
        <source>This robot reports its mode one too high (Passive as Safe, as some Wi-Fi Roomba 600s do): the true mode is shown from now on, and remembered for this robot.</source>
        <translation>Este robot informa su modo uno más alto (Passive como Safe, como algunos Roomba 600 con Wi-Fi): desde ahora se muestra el modo real y se recuerda para este robot.</translation>
    </message>
    <message>
        <source>Not sent: %1. Put it down on the floor first.</source>
        <translation>No enviado: %1. Póngalo antes en el suelo.</translation>
    </message>
    <message>
        <source>Motion sent with the %1.</source>
        <translation>Movimiento enviado con la %1.</translation>
    </message>
    <message>
        <source>Motion stopped: %1. Put it down on the floor first.</source>
        <translation>Movimiento detenido: %1. Póngalo antes en el suelo.</translation>
    </message>
    <message>
        <source>The charge fell from %1 % to %2 % as the robot guessed it again from its voltage at boot. A pack that reads full on the charger and much lower under load is worn: see Battery in the gauges.</source>
        <translation>La carga bajó del %1 % al %2 % cuando el robot volvió a estimarla a partir de su tensión al arrancar. Una batería que marca llena en el cargador y mucho menos bajo carga está gastada: vea Batería en los indicadores.</translation>
    </message>
</context>
<context>
    <name>RobotStatusBar</name>
    <message>
        <source>closed</source>
        <translation>cerrado</translation>
    </message>
    <message>
        <source>connecting</source>
        <translation>conectando</translation>
    </message>
    <message>
        <source>streaming</source>
        <translation>transmitiendo</translation>
    </message>
    <message>
        <source>stale</source>
        <translation>obsoleto</translation>
    </message>
    <message>
        <source>lost</source>
        <translation>perdido</translation>
    </message>
    <message>
        <source>reconnecting</source>
        <translation>reconectando</translation>
    </message>
    <message>
        <source>Link: %1</source>
        <translation>Enlace: %1</translation>
    </message>
    <message>
        <source>%1 frames/s</source>
        <translation>%1 tramas/s</translation>
    </message>
    <message>
        <source>checksum failures %1, resyncs %2</source>
        <translation>fallos de suma de comprobación %1, resincronizaciones %2</translation>
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
        <translation>  REPRODUCCIÓN, NO EN VIVO  </translation>
    </message>
    <message>
        <source>  NO LIVE DATA  </source>
        <translation>  SIN DATOS EN VIVO  </translation>
    </message>
    <message>
        <source>%1 messages/s from the bridge</source>
        <translation>%1 mensajes/s del puente</translation>
    </message>
    <message>
        <source>Telemetry messages from the robot&apos;s bridge, which sends only what changed. The robot&apos;s own frame rate is on its tile in the fleet view.</source>
        <translation>Mensajes de telemetría del puente del robot, que solo envía lo que cambió. La tasa de tramas propia del robot está en su ficha de la vista de la flota.</translation>
    </message>
    <message>
        <source>Roomba 500 or Create 2? (not yet identified)</source>
        <translation>¿Roomba 500 o Create 2? (aún sin identificar)</translation>
    </message>
    <message>
        <source>Recording saved: %1</source>
        <translation>Grabación guardada: %1</translation>
    </message>
    <message>
        <source>  REPLAY FINISHED  </source>
        <translation>  REPRODUCCIÓN TERMINADA  </translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>sin conexión</translation>
    </message>
    <message>
        <source>replay finished</source>
        <translation>reproducción terminada</translation>
    </message>
    <message>
        <source>replaying</source>
        <translation>reproduciendo</translation>
    </message>
    <message>
        <source>replay paused</source>
        <translation>reproducción en pausa</translation>
    </message>
    <message>
        <source>Link: replay finished</source>
        <translation>Enlace: reproducción terminada</translation>
    </message>
    <message>
        <source>Link: replaying a recording</source>
        <translation>Enlace: reproduciendo una grabación</translation>
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
        <translation>Aula</translation>
    </message>
    <message>
        <source>Empty floor</source>
        <translation>Suelo vacío</translation>
    </message>
    <message>
        <source>Table top</source>
        <translation>Tablero de mesa</translation>
    </message>
    <message>
        <source>Corridor</source>
        <translation>Pasillo</translation>
    </message>
    <message>
        <source>Dock corner</source>
        <translation>Rincón de la base</translation>
    </message>
    <message>
        <source>O&amp;pen room…</source>
        <translation>Abrir sa&amp;la…</translation>
    </message>
    <message>
        <source>Put the virtual robots in a room from a file</source>
        <translation>Poner los robots virtuales en una sala de un archivo</translation>
    </message>
    <message>
        <source>Sa&amp;ve room as…</source>
        <translation>G&amp;uardar sala como…</translation>
    </message>
    <message>
        <source>Write the virtual robots&apos; room, as edited on the map, to a file</source>
        <translation>Escribir en un archivo la sala de los robots virtuales, tal como se editó en el mapa</translation>
    </message>
    <message>
        <source>E&amp;xample rooms</source>
        <translation>Salas de e&amp;jemplo</translation>
    </message>
    <message>
        <source>&amp;Undo room edit</source>
        <translation>&amp;Deshacer cambio de sala</translation>
    </message>
    <message>
        <source>Re&amp;do room edit</source>
        <translation>Re&amp;hacer cambio de sala</translation>
    </message>
    <message>
        <source>The room of last time could not be opened: %1</source>
        <translation>No se pudo abrir la sala de la última vez: %1</translation>
    </message>
    <message>
        <source>Room opened: %1</source>
        <translation>Sala abierta: %1</translation>
    </message>
    <message>
        <source>Open room</source>
        <translation>Abrir sala</translation>
    </message>
    <message>
        <source>This room could not be opened; the room stays as it was.

%1</source>
        <translation>No se pudo abrir esta sala; la sala queda como estaba.

%1</translation>
    </message>
    <message>
        <source>Rooms (*.json);;All files (*)</source>
        <translation>Salas (*.json);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>Save room as</source>
        <translation>Guardar sala como</translation>
    </message>
    <message>
        <source>Room saved to %1</source>
        <translation>Sala guardada en %1</translation>
    </message>
    <message>
        <source>The room could not be saved.

%1</source>
        <translation>No se pudo guardar la sala.

%1</translation>
    </message>
</context>
<context>
    <name>RoomEditTool</name>
    <message>
        <source>Edit room</source>
        <translation>Editar sala</translation>
    </message>
    <message>
        <source>Add wall here</source>
        <translation>Añadir pared aquí</translation>
    </message>
    <message>
        <source>Add stage edge here</source>
        <translation>Añadir borde de escenario aquí</translation>
    </message>
    <message>
        <source>Move the virtual wall here</source>
        <translation>Mover la pared virtual aquí</translation>
    </message>
    <message>
        <source>Add virtual wall here</source>
        <translation>Añadir pared virtual aquí</translation>
    </message>
    <message>
        <source>Put the dock here</source>
        <translation>Poner la base aquí</translation>
    </message>
    <message>
        <source>Delete %1</source>
        <translation>Borrar %1</translation>
    </message>
    <message>
        <source>Editing %1: drag it or its handles · Delete removes it</source>
        <translation>Editando %1: arrastre el objeto o sus asas · Supr lo borra</translation>
    </message>
    <message>
        <source>Editing the room: click a thing to select it · right-click to add</source>
        <translation>Editando la sala: haga clic en un objeto para elegirlo · clic derecho para añadir</translation>
    </message>
    <message>
        <source>the wall</source>
        <translation>la pared</translation>
    </message>
    <message>
        <source>the stage edge</source>
        <translation>el borde del escenario</translation>
    </message>
    <message>
        <source>the dock</source>
        <translation>la base</translation>
    </message>
    <message>
        <source>the virtual wall</source>
        <translation>la pared virtual</translation>
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
        <translation>&quot;format&quot; debe ser &quot;%1&quot;</translation>
    </message>
    <message>
        <source>&quot;version&quot; %1 is not one this program reads (it reads %2)</source>
        <translation>este programa no lee la &quot;version&quot; %1 (lee la %2)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be a list</source>
        <translation>&quot;%1&quot; debe ser una lista</translation>
    </message>
    <message>
        <source>%1: a wall must have some length</source>
        <translation>%1: una pared debe tener alguna longitud</translation>
    </message>
    <message>
        <source>%1: x_min must be below x_max and y_min below y_max</source>
        <translation>%1: x_min debe ser menor que x_max e y_min menor que y_max</translation>
    </message>
    <message>
        <source>virtual_wall: &quot;range_mm&quot; must be above 0, not %1</source>
        <translation>virtual_wall: &quot;range_mm&quot; debe ser mayor que 0, no %1</translation>
    </message>
    <message>
        <source>unknown key &quot;%1&quot;</source>
        <translation>clave desconocida &quot;%1&quot;</translation>
    </message>
    <message>
        <source>%1: unknown key &quot;%2&quot;</source>
        <translation>%1: clave desconocida &quot;%2&quot;</translation>
    </message>
    <message>
        <source>%1 must be a number</source>
        <translation>%1 debe ser un número</translation>
    </message>
    <message>
        <source>%1 must be a list of %2 numbers</source>
        <translation>%1 debe ser una lista de %2 números</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be an object with x_mm, y_mm and heading_deg</source>
        <translation>&quot;%1&quot; debe ser un objeto con x_mm, y_mm y heading_deg</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is missing</source>
        <translation>%1: falta &quot;%2&quot;</translation>
    </message>
    <message>
        <source>line %1, column %2</source>
        <translation>línea %1, columna %2</translation>
    </message>
    <message>
        <source>not JSON at %1: %2</source>
        <translation>no es JSON en %1: %2</translation>
    </message>
    <message>
        <source>a room file holds one JSON object</source>
        <translation>un archivo de sala contiene un objeto JSON</translation>
    </message>
    <message>
        <source>%1: cannot read: %2</source>
        <translation>%1: no se puede leer: %2</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1: cannot write: %2</source>
        <translation>%1: no se puede escribir: %2</translation>
    </message>
    <message>
        <source>%1: the shade (the fifth number) must be from 0 (the floor as it is) to 1 (black), not %2</source>
        <translation>%1: el tono (el quinto número) debe ir de 0 (el suelo tal cual) a 1 (negro), no %2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; has %2 entries; a room holds at most %3</source>
        <translation>&quot;%1&quot; tiene %2 entradas; una sala admite como máximo %3</translation>
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
        <translation>se esperaba NOMBRE:VALORES:NOTAS, p. ej. &quot;Beep:d=4,o=5,b=120:c,e,g&quot;</translation>
    </message>
    <message>
        <source>default &quot;%1&quot; is not KEY=NUMBER</source>
        <translation>el valor predeterminado &quot;%1&quot; no es CLAVE=NÚMERO</translation>
    </message>
    <message>
        <source>default &quot;%1&quot; is not valid (d: 1..32, o: 4..7, b: 1..900)</source>
        <translation>el valor predeterminado &quot;%1&quot; no es válido (d: 1..32, o: 4..7, b: 1..900)</translation>
    </message>
    <message>
        <source>the tune has no notes</source>
        <translation>la melodía no tiene notas</translation>
    </message>
    <message>
        <source>note %1 &quot;%2&quot;: %3</source>
        <translation>nota %1 &quot;%2&quot;: %3</translation>
    </message>
    <message>
        <source>duration must be 1, 2, 4, 8, 16 or 32</source>
        <translation>la duración debe ser 1, 2, 4, 8, 16 o 32</translation>
    </message>
    <message>
        <source>no note letter</source>
        <translation>falta la letra de la nota</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a note (a..g, h) or pause (p)</source>
        <translation>&quot;%1&quot; no es una nota (a..g, h) ni una pausa (p)</translation>
    </message>
    <message>
        <source>octave must be 4..7</source>
        <translation>la octava debe ser 4..7</translation>
    </message>
    <message>
        <source>unexpected &quot;%1&quot;</source>
        <translation>&quot;%1&quot; inesperado</translation>
    </message>
    <message>
        <source>lasts %1/64 s at %2 beats per minute; a note lasts 1..255</source>
        <translation>dura %1/64 s a %2 pulsos por minuto; una nota dura 1..255</translation>
    </message>
</context>
<context>
    <name>RunComparison</name>
    <message>
        <source>Show a second recording beside this run: plots and map, in a style of its own</source>
        <translation>Mostrar una segunda grabación junto a este recorrido: gráficas y mapa, con un estilo propio</translation>
    </message>
    <message>
        <source>Comparison</source>
        <translation>Comparación</translation>
    </message>
    <message>
        <source>Compare with recording</source>
        <translation>Comparar con grabación</translation>
    </message>
    <message>
        <source>Roomba Dashboard recordings (*.oirec);;All files (*)</source>
        <translation>Grabaciones de Roomba Dashboard (*.oirec);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>This file cannot be compared.

%1</source>
        <translation>Este archivo no se puede comparar.

%1</translation>
    </message>
    <message>
        <source>&amp;Compare with recording…</source>
        <translation>&amp;Comparar con grabación…</translation>
    </message>
    <message>
        <source>C&amp;lose comparison</source>
        <translation>Ce&amp;rrar comparación</translation>
    </message>
</context>
<context>
    <name>RxFrameScanner</name>
    <message>
        <source>text &quot;%1&quot;</source>
        <translation>texto &quot;%1&quot;</translation>
    </message>
    <message>
        <source>outside any stream frame</source>
        <translation>fuera de toda trama del flujo de datos</translation>
    </message>
    <message>
        <source>stream frame: %1</source>
        <translation>trama del flujo de datos: %1</translation>
    </message>
    <message>
        <source>reply: %1</source>
        <translation>respuesta: %1</translation>
    </message>
</context>
<context>
    <name>ScheduleEditor</name>
    <message>
        <source>Sunday</source>
        <translation>Domingo</translation>
    </message>
    <message>
        <source>Monday</source>
        <translation>Lunes</translation>
    </message>
    <message>
        <source>Tuesday</source>
        <translation>Martes</translation>
    </message>
    <message>
        <source>Wednesday</source>
        <translation>Miércoles</translation>
    </message>
    <message>
        <source>Thursday</source>
        <translation>Jueves</translation>
    </message>
    <message>
        <source>Friday</source>
        <translation>Viernes</translation>
    </message>
    <message>
        <source>Saturday</source>
        <translation>Sábado</translation>
    </message>
    <message>
        <source>Weekly cleaning schedule (167)</source>
        <translation>Programación semanal de limpieza (167)</translation>
    </message>
    <message>
        <source>Cleaning time on %1</source>
        <translation>Hora de limpieza: %1</translation>
    </message>
    <message>
        <source>Send Schedule</source>
        <translation>Enviar programación</translation>
    </message>
    <message>
        <source>Disable all</source>
        <translation>Desactivar todo</translation>
    </message>
    <message>
        <source>Clear every day and send a schedule with no cleaning</source>
        <translation>Borra todos los días y envía una programación sin limpiezas</translation>
    </message>
    <message>
        <source>Nothing sent yet. The robot cannot report its schedule, so this shows what was last sent from here.</source>
        <translation>Aún no se ha enviado nada. El robot no puede informar de su programación, así que aquí se muestra lo último que se envió desde este equipo.</translation>
    </message>
    <message>
        <source>Last sent: %1 at %2</source>
        <translation>Último envío: %1 a las %2</translation>
    </message>
    <message>
        <source>Presets</source>
        <translation>Preajustes</translation>
    </message>
    <message>
        <source>Saved presets</source>
        <translation>Preajustes guardados</translation>
    </message>
    <message>
        <source>Load</source>
        <translation>Cargar</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Eliminar</translation>
    </message>
    <message>
        <source>Preset name</source>
        <translation>Nombre del preajuste</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Guardar</translation>
    </message>
    <message>
        <source>Save the grid under this name</source>
        <translation>Guarda la cuadrícula con este nombre</translation>
    </message>
    <message>
        <source>Robot clock (168)</source>
        <translation>Reloj del robot (168)</translation>
    </message>
    <message>
        <source>Set from this computer&apos;s clock</source>
        <translation>Tomar del reloj de este equipo</translation>
    </message>
    <message>
        <source>Day for the robot clock</source>
        <translation>Día para el reloj del robot</translation>
    </message>
    <message>
        <source>Time for the robot clock</source>
        <translation>Hora para el reloj del robot</translation>
    </message>
    <message>
        <source>Set Day/Time</source>
        <translation>Ajustar día/hora</translation>
    </message>
    <message>
        <source>The %1 has no cleaning schedule or clock: Schedule (167) and Set Day/Time (168) are Roomba 500 / Create 2 only.</source>
        <translation>El %1 no tiene programación de limpieza ni reloj: Schedule (167) y Set Day/Time (168) son solo para Roomba 500 / Create 2.</translation>
    </message>
    <message>
        <source>Will send: %1</source>
        <translation>Enviará: %1</translation>
    </message>
    <message>
        <source>Not sent: %1</source>
        <translation>No enviado: %1</translation>
    </message>
    <message>
        <source>Sent: no scheduled cleaning.</source>
        <translation>Enviado: ninguna limpieza programada.</translation>
    </message>
    <message>
        <source>Schedule sent.</source>
        <translation>Programación enviada.</translation>
    </message>
    <message>
        <source>Robot clock set to %1 %2.</source>
        <translation>Reloj del robot ajustado a %1 %2.</translation>
    </message>
    <message>
        <source>Not saved: give the preset a name.</source>
        <translation>No guardado: asigne un nombre al preajuste.</translation>
    </message>
    <message>
        <source>Preset &quot;%1&quot; replaced.</source>
        <translation>Preajuste &quot;%1&quot; reemplazado.</translation>
    </message>
    <message>
        <source>Preset &quot;%1&quot; saved.</source>
        <translation>Preajuste &quot;%1&quot; guardado.</translation>
    </message>
    <message>
        <source>No preset named &quot;%1&quot;.</source>
        <translation>No hay ningún preajuste llamado &quot;%1&quot;.</translation>
    </message>
    <message>
        <source>Preset &quot;%1&quot; is damaged: %2</source>
        <translation>El preajuste &quot;%1&quot; está dañado: %2</translation>
    </message>
    <message>
        <source>Preset &quot;%1&quot; loaded; press Send Schedule to send it.</source>
        <translation>Preajuste &quot;%1&quot; cargado; pulse Enviar programación para enviarlo.</translation>
    </message>
    <message>
        <source>Preset &quot;%1&quot; deleted.</source>
        <translation>Preajuste &quot;%1&quot; eliminado.</translation>
    </message>
</context>
<context>
    <name>ScriptEditor</name>
    <message>
        <source>Drive 40 cm and stop</source>
        <translation>Conducir 40 cm y parar</translation>
    </message>
    <message>
        <source>Toggle LED on bump</source>
        <translation>Cambiar LED al chocar</translation>
    </message>
    <message>
        <source>Drive in a square</source>
        <translation>Conducir en cuadrado</translation>
    </message>
    <message>
        <source>Load an example…</source>
        <translation>Cargar un ejemplo…</translation>
    </message>
    <message>
        <source>Example scripts</source>
        <translation>Scripts de ejemplo</translation>
    </message>
    <message>
        <source>One command a line, e.g.
%1</source>
        <translation>Un comando por línea, p. ej.
%1</translation>
    </message>
    <message>
        <source>Script</source>
        <translation>Script</translation>
    </message>
    <message>
        <source>Upload (152)</source>
        <translation>Subir (152)</translation>
    </message>
    <message>
        <source>Play (153)</source>
        <translation>Ejecutar (153)</translation>
    </message>
    <message>
        <source>Run the stored script</source>
        <translation>Ejecuta el script almacenado</translation>
    </message>
    <message>
        <source>Show Script (154)</source>
        <translation>Mostrar script (154)</translation>
    </message>
    <message>
        <source>Read the stored script back and compare it with what was uploaded</source>
        <translation>Lee el script almacenado y lo compara con lo que se subió</translation>
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
        <translation>Los scripts y las demos son solo para el Create original: %1.</translation>
    </message>
    <message>
        <source>? / %1 bytes</source>
        <translation>? / %1 bytes</translation>
    </message>
    <message>
        <source>0 / %1 bytes</source>
        <translation>0 / %1 bytes</translation>
    </message>
    <message>
        <source>Line %1: %2</source>
        <translation>Línea %1: %2</translation>
    </message>
    <message>
        <source>%1 / %2 bytes</source>
        <translation>%1 / %2 bytes</translation>
    </message>
    <message>
        <source>The script is %1 bytes; the robot stores at most %2. Remove %3 bytes to upload it.</source>
        <translation>El script ocupa %1 bytes; el robot almacena como máximo %2. Quite %3 bytes para subirlo.</translation>
    </message>
    <message>
        <source>%1. %2</source>
        <translation>%1. %2</translation>
    </message>
    <message>
        <source>Store the script on the robot (152)</source>
        <translation>Almacena el script en el robot (152)</translation>
    </message>
    <message>
        <source>Fix the script before uploading it</source>
        <translation>Corrija el script antes de subirlo</translation>
    </message>
    <message>
        <source>(empty)</source>
        <translation>(vacío)</translation>
    </message>
    <message>
        <source>%1 (not readable: %2)</source>
        <translation>%1 (no legible: %2)</translation>
    </message>
    <message>
        <source>The robot&apos;s script matches what was sent: %1</source>
        <translation>El script del robot coincide con lo enviado: %1</translation>
    </message>
    <message>
        <source>The robot&apos;s script differs from what was sent.
On the robot: %1
Sent: %2</source>
        <translation>El script del robot difiere de lo enviado.
En el robot: %1
Enviado: %2</translation>
    </message>
    <message>
        <source>nothing uploaded yet</source>
        <translation>aún no se ha subido nada</translation>
    </message>
    <message>
        <source>Asking for the robot&apos;s script…</source>
        <translation>Pidiendo al robot su script…</translation>
    </message>
    <message>
        <source>No script came back: %1</source>
        <translation>No volvió ningún script: %1</translation>
    </message>
    <message>
        <source>Uploaded (152): %1 / %2 bytes. Play (153) runs the script; Show Script (154) reads it back.</source>
        <translation>Subido (152): %1 / %2 bytes. Play (153) ejecuta el script; Show Script (154) lo lee de vuelta.</translation>
    </message>
    <message>
        <source>Play (153) sent. While the script waits (155–158) the Create hears no command, not even a stop; it listens again when the script ends.</source>
        <translation>Play (153) enviado. Mientras el script espera (155–158), el Create no oye ninguna orden, ni siquiera una parada; vuelve a escuchar cuando el script termina.</translation>
    </message>
</context>
<context>
    <name>SelectedRobotView</name>
    <message>
        <source>Recording stopped: %1</source>
        <translation>Grabación detenida: %1</translation>
    </message>
    <message>
        <source>A recording is replayed: there is no robot to command. Select a connected robot.</source>
        <translation>Se reproduce una grabación: no hay ningún robot al que dar órdenes. Seleccione un robot conectado.</translation>
    </message>
    <message>
        <source>Not connected: choose the robot&apos;s connection above and press Connect.</source>
        <translation>Sin conexión: elija arriba la conexión del robot y pulse Conectar.</translation>
    </message>
    <message>
        <source>Connecting to the robot: the commands work once it answers.</source>
        <translation>Conectando con el robot: las órdenes funcionan en cuanto responda.</translation>
    </message>
    <message>
        <source>The link to the robot is lost: the commands work again once it reconnects.</source>
        <translation>Se perdió el enlace con el robot: las órdenes vuelven a funcionar en cuanto se reconecte.</translation>
    </message>
</context>
<context>
    <name>SensorGauges</name>
    <message>
        <source>STALE — no fresh data from the robot</source>
        <translation>OBSOLETO — no hay datos recientes del robot</translation>
    </message>
    <message>
        <source>Battery</source>
        <translation>Batería</translation>
    </message>
    <message>
        <source>Drive</source>
        <translation>Conducción</translation>
    </message>
    <message>
        <source>Motors and dirt</source>
        <translation>Motores y suciedad</translation>
    </message>
    <message>
        <source>Cargo bay</source>
        <translation>Bahía de carga</translation>
    </message>
    <message>
        <source>Charge</source>
        <translation>Carga</translation>
    </message>
    <message>
        <source>Current</source>
        <translation>Corriente</translation>
    </message>
    <message>
        <source>Temperature</source>
        <translation>Temperatura</translation>
    </message>
    <message>
        <source>Charging</source>
        <translation>Carga</translation>
    </message>
    <message>
        <source>Charging sources</source>
        <translation>Fuentes de carga</translation>
    </message>
    <message>
        <source>Requested velocity</source>
        <translation>Velocidad solicitada</translation>
    </message>
    <message>
        <source>Requested radius</source>
        <translation>Radio solicitado</translation>
    </message>
    <message>
        <source>Left wheel motor</source>
        <translation>Motor rueda izquierda</translation>
    </message>
    <message>
        <source>Right wheel motor</source>
        <translation>Motor rueda derecha</translation>
    </message>
    <message>
        <source>Main brush motor</source>
        <translation>Motor cepillo principal</translation>
    </message>
    <message>
        <source>Side brush motor</source>
        <translation>Motor cepillo lateral</translation>
    </message>
    <message>
        <source>Dirt detect</source>
        <translation>Detección de suciedad</translation>
    </message>
    <message>
        <source>Analog input</source>
        <translation>Entrada analógica</translation>
    </message>
    <message>
        <source>Baud rate change</source>
        <translation>Cambio de baudios</translation>
    </message>
    <message>
        <source>Digital input %1</source>
        <translation>Entrada digital %1</translation>
    </message>
    <message>
        <source>%1 of %2 mAh</source>
        <translation>%1 de %2 mAh</translation>
    </message>
    <message>
        <source>discharging</source>
        <translation>descargando</translation>
    </message>
    <message>
        <source>charging</source>
        <translation>cargando</translation>
    </message>
    <message>
        <source>no current</source>
        <translation>sin corriente</translation>
    </message>
    <message>
        <source>Not charging</source>
        <translation>Sin cargar</translation>
    </message>
    <message>
        <source>Reconditioning</source>
        <translation>Reacondicionando</translation>
    </message>
    <message>
        <source>Full charging</source>
        <translation>Carga completa</translation>
    </message>
    <message>
        <source>Trickle charging</source>
        <translation>Carga de mantenimiento</translation>
    </message>
    <message>
        <source>Waiting</source>
        <translation>En espera</translation>
    </message>
    <message>
        <source>Charging fault</source>
        <translation>Fallo de carga</translation>
    </message>
    <message>
        <source>Unknown (%1)</source>
        <translation>Desconocido (%1)</translation>
    </message>
    <message>
        <source>none</source>
        <translation>ninguna</translation>
    </message>
    <message>
        <source> + </source>
        <translation> + </translation>
    </message>
    <message>
        <source>forward</source>
        <translation>adelante</translation>
    </message>
    <message>
        <source>backward</source>
        <translation>atrás</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>detenido</translation>
    </message>
    <message>
        <source>straight</source>
        <translation>recto</translation>
    </message>
    <message>
        <source>radius %1</source>
        <translation>radio %1</translation>
    </message>
    <message>
        <source>turn in place cw</source>
        <translation>giro en el sitio, horario</translation>
    </message>
    <message>
        <source>radius -1</source>
        <translation>radio -1</translation>
    </message>
    <message>
        <source>turn in place ccw</source>
        <translation>giro en el sitio, antihorario</translation>
    </message>
    <message>
        <source>radius 1</source>
        <translation>radio 1</translation>
    </message>
    <message>
        <source>turning left</source>
        <translation>girando a la izquierda</translation>
    </message>
    <message>
        <source>turning right</source>
        <translation>girando a la derecha</translation>
    </message>
    <message>
        <source>%1 V on pin 4</source>
        <translation>%1 V en el pin 4</translation>
    </message>
    <message>
        <source>high</source>
        <translation>alto</translation>
    </message>
    <message>
        <source>low</source>
        <translation>bajo</translation>
    </message>
    <message>
        <source>pin %1</source>
        <translation>pin %1</translation>
    </message>
    <message>
        <source>asserted (low)</source>
        <translation>activa (baja)</translation>
    </message>
    <message>
        <source>idle (high)</source>
        <translation>inactiva (alta)</translation>
    </message>
    <message>
        <source>Voltage</source>
        <translation>Tensión</translation>
    </message>
    <message>
        <source>REPLAY FINISHED — the recording has ended</source>
        <translation>REPRODUCCIÓN TERMINADA — la grabación ha terminado</translation>
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
        <translation>Medido el %1, en una conexión anterior.</translation>
    </message>
    <message>
        <source>Capacity measured so far: %1.</source>
        <translation>Capacidad medida hasta ahora: %1.</translation>
    </message>
    <message>
        <source>Pack health</source>
        <translation>Estado de la batería</translation>
    </message>
    <message>
        <source>%1, estimated from voltage</source>
        <translation>%1, estimado a partir de la tensión</translation>
    </message>
    <message>
        <source>The robot guessed this charge from its voltage as it booted: until a full charge it is an estimate, and a worn pack&apos;s voltage sags under load, so it reads low.</source>
        <translation>El robot estimó esta carga a partir de su tensión al arrancar: hasta una carga completa es una estimación, y la tensión de una batería gastada cae bajo carga, así que marca de menos.</translation>
    </message>
</context>
<context>
    <name>SensorHistory</name>
    <message>
        <source>No channels to export.</source>
        <translation>No hay canales para exportar.</translation>
    </message>
    <message>
        <source>The time range to export is not a number.</source>
        <translation>El intervalo de tiempo para exportar no es un número.</translation>
    </message>
    <message>
        <source>Packet %1 is not a sensor packet of the %2.</source>
        <translation>El paquete %1 no es un paquete de sensores del %2.</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>No se puede escribir %1: %2</translation>
    </message>
    <message>
        <source>Cannot save %1: %2</source>
        <translation>No se puede guardar %1: %2</translation>
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
        <translation>Pausa o reanuda el seguimiento de la muestra más reciente (barra espaciadora)</translation>
    </message>
    <message>
        <source>How much time the plots show</source>
        <translation>Cuánto tiempo muestran las gráficas</translation>
    </message>
    <message>
        <source>&amp;Window</source>
        <translation>&amp;Ventana</translation>
    </message>
    <message>
        <source>Add plot</source>
        <translation>Añadir gráfica</translation>
    </message>
    <message>
        <source>Add another plot below the others</source>
        <translation>Añade otra gráfica debajo de las demás</translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation>Exportar CSV</translation>
    </message>
    <message>
        <source>Write the plotted channels to a CSV file</source>
        <translation>Escribe los canales representados en un archivo CSV</translation>
    </message>
    <message>
        <source>Visible range…</source>
        <translation>Intervalo visible…</translation>
    </message>
    <message>
        <source>Whole history…</source>
        <translation>Todo el historial…</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Reanudar</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pausa</translation>
    </message>
    <message>
        <source>Live</source>
        <translation>En vivo</translation>
    </message>
    <message>
        <source>There is no sensor history to export.</source>
        <translation>No hay historial de sensores para exportar.</translation>
    </message>
    <message>
        <source>No channels are plotted.</source>
        <translation>No se representa ningún canal.</translation>
    </message>
    <message>
        <source>Export the visible range</source>
        <translation>Exportar el intervalo visible</translation>
    </message>
    <message>
        <source>Export the whole history</source>
        <translation>Exportar todo el historial</translation>
    </message>
    <message>
        <source>CSV files (*.csv);;All files (*)</source>
        <translation>Archivos CSV (*.csv);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Error al exportar</translation>
    </message>
    <message>
        <source>Paused: drag or arrows pan, wheel or +/- zoom, Space resumes</source>
        <translation>En pausa: arrastre o flechas para desplazar, rueda o +/- para ampliar, barra espaciadora para continuar</translation>
    </message>
    <message>
        <source>Not live: no fresh data</source>
        <translation>No en directo: sin datos nuevos</translation>
    </message>
    <message>
        <source>Replay finished</source>
        <translation>Reproducción terminada</translation>
    </message>
    <message>
        <source>Replay, not live</source>
        <translation>Reproducción, no en vivo</translation>
    </message>
</context>
<context>
    <name>SettingsFile</name>
    <message>
        <source>file damaged</source>
        <translation>archivo dañado</translation>
    </message>
    <message>
        <source>file unreadable</source>
        <translation>archivo ilegible</translation>
    </message>
    <message>
        <source>settings version %1, not %2</source>
        <translation>versión de ajustes %1, no %2</translation>
    </message>
    <message>
        <source>Settings not loaded (%1) and not kept aside: %2</source>
        <translation>Ajustes no cargados (%1) ni apartados: %2</translation>
    </message>
    <message>
        <source>Settings reset to defaults: %1; kept as %2</source>
        <translation>Ajustes restablecidos a los valores predeterminados: %1; guardado como %2</translation>
    </message>
</context>
<context>
    <name>SevenSegmentDisplay</name>
    <message>
        <source>digit %1 dark</source>
        <translation>dígito %1 apagado</translation>
    </message>
    <message>
        <source>digit %1 segments %2</source>
        <translation>dígito %1 segmentos %2</translation>
    </message>
    <message>
        <source>Lit: %1.</source>
        <translation>Encendidos: %1.</translation>
    </message>
    <message>
        <source>Arrow keys choose a segment, Space switches it.</source>
        <translation>Las flechas eligen un segmento y la barra espaciadora lo cambia.</translation>
    </message>
</context>
<context>
    <name>SignalBars</name>
    <message>
        <source>L</source>
        <translation>I</translation>
    </message>
    <message>
        <source>FL</source>
        <translation>DI</translation>
    </message>
    <message>
        <source>FR</source>
        <translation>DD</translation>
    </message>
    <message>
        <source>R</source>
        <translation>D</translation>
    </message>
    <message>
        <source>CL</source>
        <translation>CI</translation>
    </message>
    <message>
        <source>CR</source>
        <translation>CD</translation>
    </message>
    <message>
        <source>Cliff</source>
        <translation>Desnivel</translation>
    </message>
    <message>
        <source>Light bump</source>
        <translation>Parachoques de luz</translation>
    </message>
    <message>
        <source>Signal bars</source>
        <translation>Barras de señal</translation>
    </message>
    <message>
        <source>cliff</source>
        <comment>under a bar</comment>
        <translation>desnivel</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Luz</translation>
    </message>
    <message>
        <source>light</source>
        <comment>under a bar</comment>
        <translation>luz</translation>
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
        <translation>Obsoleto: %1</translation>
    </message>
    <message>
        <source>Cliff and light-bump signals</source>
        <translation>Señales de desnivel y de parachoques de luz</translation>
    </message>
    <message>
        <source>Cliff signals</source>
        <translation>Señales de desnivel</translation>
    </message>
    <message>
        <source>STALE — %1</source>
        <translation>OBSOLETO — %1</translation>
    </message>
</context>
<context>
    <name>SongComposer</name>
    <message>
        <source>Song slot:</source>
        <translation>Ranura de canción:</translation>
    </message>
    <message>
        <source>Song slots</source>
        <translation>Ranuras de canción</translation>
    </message>
    <message>
        <source>Add note</source>
        <translation>Añadir nota</translation>
    </message>
    <message>
        <source>Add a note after the selected one</source>
        <translation>Añade una nota después de la seleccionada</translation>
    </message>
    <message>
        <source>Remove note</source>
        <translation>Quitar nota</translation>
    </message>
    <message>
        <source>Remove the selected note</source>
        <translation>Quita la nota seleccionada</translation>
    </message>
    <message>
        <source> st</source>
        <translation> st</translation>
    </message>
    <message>
        <source>Semitones to transpose by; negative is down</source>
        <translation>Semitonos que transponer; negativo es hacia abajo</translation>
    </message>
    <message>
        <source>Semitones</source>
        <translation>Semitonos</translation>
    </message>
    <message>
        <source>Transpose</source>
        <translation>Transponer</translation>
    </message>
    <message>
        <source>Move every note by the semitones shown</source>
        <translation>Mueve todas las notas los semitonos indicados</translation>
    </message>
    <message>
        <source>Multiply every duration: 2 plays twice as slow, 0.5 twice as fast</source>
        <translation>Multiplica todas las duraciones: 2 suena el doble de lento, 0.5 el doble de rápido</translation>
    </message>
    <message>
        <source>Duration factor</source>
        <translation>Factor de duración</translation>
    </message>
    <message>
        <source>Scale durations</source>
        <translation>Escalar duraciones</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>Nota</translation>
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
        <translation>Nota: un nombre como C#5, un número MIDI 31..127 o &quot;silencio&quot;. Duración en 1/64 s (0..255) o en milisegundos.</translation>
    </message>
    <message>
        <source>Notes</source>
        <translation>Notas</translation>
    </message>
    <message>
        <source>One row a note: the note, its duration in 1/64 s and in ms. Arrow keys move, F2 or typing edits a cell.</source>
        <translation>Una fila por nota: la nota, su duración en 1/64 s y en ms. Las flechas mueven; F2 o escribir edita una celda.</translation>
    </message>
    <message>
        <source>Upload slot</source>
        <translation>Subir ranura</translation>
    </message>
    <message>
        <source>Send this slot&apos;s song to the robot (140)</source>
        <translation>Envía al robot la canción de esta ranura (140)</translation>
    </message>
    <message>
        <source>Upload all</source>
        <translation>Subir todas</translation>
    </message>
    <message>
        <source>Send every slot that has notes (140)</source>
        <translation>Envía todas las ranuras que tienen notas (140)</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Reproducir</translation>
    </message>
    <message>
        <source>Upload this slot&apos;s song and play it on the robot (140, 141)</source>
        <translation>Sube la canción de esta ranura y la reproduce en el robot (140, 141)</translation>
    </message>
    <message>
        <source>Stop preview</source>
        <translation>Detener vista previa</translation>
    </message>
    <message>
        <source>Preview</source>
        <translation>Vista previa</translation>
    </message>
    <message>
        <source>Play this slot on the computer</source>
        <translation>Reproduce esta ranura en el equipo</translation>
    </message>
    <message>
        <source>Square tone</source>
        <translation>Onda cuadrada</translation>
    </message>
    <message>
        <source>Sine tone</source>
        <translation>Onda sinusoidal</translation>
    </message>
    <message>
        <source>How Preview and Export WAV sound; the robot&apos;s speaker sounds closer to square</source>
        <translation>Cómo suenan Vista previa y Exportar WAV; el altavoz del robot se parece más a la onda cuadrada</translation>
    </message>
    <message>
        <source>Tone for Preview and Export WAV</source>
        <translation>Tono para Vista previa y Exportar WAV</translation>
    </message>
    <message>
        <source>Load…</source>
        <translation>Cargar…</translation>
    </message>
    <message>
        <source>Replace the songs with a song file</source>
        <translation>Sustituye las canciones por un archivo de canciones</translation>
    </message>
    <message>
        <source>Save…</source>
        <translation>Guardar…</translation>
    </message>
    <message>
        <source>Save the songs as JSON</source>
        <translation>Guarda las canciones como JSON</translation>
    </message>
    <message>
        <source>Examples</source>
        <translation>Ejemplos</translation>
    </message>
    <message>
        <source>Put an example song in this slot</source>
        <translation>Pone una canción de ejemplo en esta ranura</translation>
    </message>
    <message>
        <source>Import RTTTL…</source>
        <translation>Importar RTTTL…</translation>
    </message>
    <message>
        <source>Notes from a ring-tone text</source>
        <translation>Notas de un texto de tono de llamada</translation>
    </message>
    <message>
        <source>Import MIDI…</source>
        <translation>Importar MIDI…</translation>
    </message>
    <message>
        <source>The melody of a MIDI file</source>
        <translation>La melodía de un archivo MIDI</translation>
    </message>
    <message>
        <source>Export WAV…</source>
        <translation>Exportar WAV…</translation>
    </message>
    <message>
        <source>This slot as a WAV sound file</source>
        <translation>Esta ranura como archivo de sonido WAV</translation>
    </message>
    <message>
        <source>Preview plays on %1.</source>
        <translation>La vista previa suena en %1.</translation>
    </message>
    <message>
        <source>No audio output device on this computer, so Preview is off. Export WAV still works.</source>
        <translation>Este equipo no tiene dispositivo de salida de audio, así que Vista previa está desactivada. Exportar WAV sigue funcionando.</translation>
    </message>
    <message>
        <source>Load songs</source>
        <translation>Cargar canciones</translation>
    </message>
    <message>
        <source>Song files (*.json)</source>
        <translation>Archivos de canciones (*.json)</translation>
    </message>
    <message>
        <source>Save songs</source>
        <translation>Guardar canciones</translation>
    </message>
    <message>
        <source>Import RTTTL</source>
        <translation>Importar RTTTL</translation>
    </message>
    <message>
        <source>Ring tone, e.g. Beep:d=4,o=5,b=120:c,e,g,c6</source>
        <translation>Tono de llamada, p. ej. Beep:d=4,o=5,b=120:c,e,g,c6</translation>
    </message>
    <message>
        <source>Import MIDI</source>
        <translation>Importar MIDI</translation>
    </message>
    <message>
        <source>MIDI files (*.mid *.midi)</source>
        <translation>Archivos MIDI (*.mid *.midi)</translation>
    </message>
    <message>
        <source>Export WAV</source>
        <translation>Exportar WAV</translation>
    </message>
    <message>
        <source>WAV files (*.wav)</source>
        <translation>Archivos WAV (*.wav)</translation>
    </message>
    <message>
        <source>The %1 has %2 song slots; %3 song(s) in higher slots are kept but hidden.</source>
        <translation>El %1 tiene %2 ranuras de canción; %3 canción(es) en ranuras superiores se conservan pero quedan ocultas.</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Song %1: 1 note</source>
        <translation>Canción %1: 1 nota</translation>
    </message>
    <message numerus="yes">
        <source>Song %1: %n notes</source>
        <translation>
            <numerusform>Canción %1: %n nota</numerusform>
            <numerusform>Canción %1: %n notas</numerusform>
        </translation>
    </message>
    <message>
        <source>Song slot %1 is outside 0..%2 on this robot</source>
        <translation>La ranura de canción %1 está fuera de 0..%2 en este robot</translation>
    </message>
    <message>
        <source>A song holds at most %1 notes, not %2</source>
        <translation>Una canción admite como máximo %1 notas, no %2</translation>
    </message>
    <message>
        <source>Slot %1: %2, %3 s (%4/64 s)</source>
        <translation>Ranura %1: %2, %3 s (%4/64 s)</translation>
    </message>
    <message>
        <source>1 note</source>
        <translation>1 nota</translation>
    </message>
    <message numerus="yes">
        <source>%n notes</source>
        <translation>
            <numerusform>%n nota</numerusform>
            <numerusform>%n notas</numerusform>
        </translation>
    </message>
    <message>
        <source>Note %1: &quot;%2&quot; is not a note. Use a name from G1 to G9 (e.g. C#5), a MIDI number 31..127, or &quot;rest&quot;.</source>
        <translation>Nota %1: &quot;%2&quot; no es una nota. Use un nombre de G1 a G9 (p. ej. C#5), un número MIDI 31..127 o &quot;silencio&quot;.</translation>
    </message>
    <message>
        <source>Note %1: &quot;%2&quot; is not a whole number of 1/64 s</source>
        <translation>Nota %1: &quot;%2&quot; no es un número entero de 1/64 s</translation>
    </message>
    <message>
        <source>Note %1: &quot;%2&quot; is not a number of milliseconds</source>
        <translation>Nota %1: &quot;%2&quot; no es un número de milisegundos</translation>
    </message>
    <message>
        <source>Note %1: %2 is outside 0..255/64 s (0..3984 ms)</source>
        <translation>Nota %1: %2 está fuera de 0..255/64 s (0..3984 ms)</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>A song holds at most %1 notes</source>
        <translation>Una canción admite como máximo %1 notas</translation>
    </message>
    <message>
        <source>Transposed slot %1 by %2 semitone(s).</source>
        <translation>Ranura %1 transpuesta %2 semitono(s).</translation>
    </message>
    <message>
        <source>Durations in slot %1 multiplied by %2.</source>
        <translation>Duraciones de la ranura %1 multiplicadas por %2.</translation>
    </message>
    <message>
        <source>%1 refused: %2</source>
        <translation>%1 rechazado: %2</translation>
    </message>
    <message>
        <source>%1 Warning: %2</source>
        <translation>%1 Advertencia: %2</translation>
    </message>
    <message>
        <source>%1 sent.</source>
        <translation>%1 enviado.</translation>
    </message>
    <message>
        <source>Song %1</source>
        <translation>Canción %1</translation>
    </message>
    <message>
        <source>Song %1 refused: %2</source>
        <translation>Canción %1 rechazada: %2</translation>
    </message>
    <message>
        <source>Nothing to upload: every slot is empty.</source>
        <translation>Nada que subir: todas las ranuras están vacías.</translation>
    </message>
    <message>
        <source>Uploaded songs %1.</source>
        <translation>Canciones subidas: %1.</translation>
    </message>
    <message>
        <source> Warning: </source>
        <translation> Advertencia: </translation>
    </message>
    <message>
        <source>Play song %1</source>
        <translation>Reproducir canción %1</translation>
    </message>
    <message>
        <source>Playing: unknown (packet 37 not streamed)</source>
        <translation>Reproduciendo: desconocido (el paquete 37 no está en el flujo de datos)</translation>
    </message>
    <message>
        <source>No song playing</source>
        <translation>Ninguna canción en reproducción</translation>
    </message>
    <message>
        <source>Playing song %1: %2 of %3 s</source>
        <translation>Reproduciendo canción %1: %2 de %3 s</translation>
    </message>
    <message>
        <source>Playing song %1</source>
        <translation>Reproduciendo canción %1</translation>
    </message>
    <message>
        <source>Saved %1.</source>
        <translation>Se guardó %1.</translation>
    </message>
    <message>
        <source> The open songs are unchanged.</source>
        <translation> Las canciones abiertas no han cambiado.</translation>
    </message>
    <message>
        <source>Loaded %1.</source>
        <translation>Se cargó %1.</translation>
    </message>
    <message>
        <source>%1 needs %2 slot(s) but only %3 are left from slot %4 on; nothing was changed.</source>
        <translation>%1 necesita %2 ranura(s), pero solo quedan %3 a partir de la ranura %4; no se cambió nada.</translation>
    </message>
    <message>
        <source>%1 is in slot %2.</source>
        <translation>%1 está en la ranura %2.</translation>
    </message>
    <message>
        <source>The ring tone</source>
        <translation>El tono de llamada</translation>
    </message>
    <message>
        <source>%1: %2 notes in slot(s) %3..%4.</source>
        <translation>%1: %2 notas en la(s) ranura(s) %3..%4.</translation>
    </message>
    <message>
        <source>Imported %1 melody notes into slot(s) %2..%3.</source>
        <translation>Se importaron %1 notas de la melodía en la(s) ranura(s) %2..%3.</translation>
    </message>
    <message>
        <source> %1 notes did not fit in the remaining slots and were left out.</source>
        <translation> %1 notas no cabían en las ranuras restantes y se omitieron.</translation>
    </message>
    <message>
        <source> %1 notes longer than 255/64 s were shortened to 255.</source>
        <translation> %1 notas de más de 255/64 s se acortaron a 255.</translation>
    </message>
    <message>
        <source>Slot %1 is empty; there is nothing to export.</source>
        <translation>La ranura %1 está vacía; no hay nada que exportar.</translation>
    </message>
    <message>
        <source>Exported slot %1 to %2.</source>
        <translation>Ranura %1 exportada a %2.</translation>
    </message>
    <message>
        <source>No audio output device on this computer, so Preview is off.</source>
        <translation>Este equipo no tiene dispositivo de salida de audio, así que Vista previa está desactivada.</translation>
    </message>
    <message>
        <source>Slot %1 is empty; there is nothing to preview.</source>
        <translation>La ranura %1 está vacía; no hay nada que previsualizar.</translation>
    </message>
    <message>
        <source>%1 cannot play 16-bit mono sound at %2 Hz; use Export WAV instead.</source>
        <translation>%1 no puede reproducir sonido mono de 16 bits a %2 Hz; use Exportar WAV en su lugar.</translation>
    </message>
    <message>
        <source>Play song %1 refused: %2</source>
        <translation>Reproducir la canción %1 rechazado: %2</translation>
    </message>
    <message>
        <source>song slot 4 may not play on some firmware (ERRATA 13)</source>
        <translation>la ranura de canción 4 puede no sonar en algunos firmwares (ERRATA 13)</translation>
    </message>
    <message>
        <source>Nothing to play: slot %1 has no notes.</source>
        <translation>Nada que reproducir: la ranura %1 no tiene notas.</translation>
    </message>
    <message>
        <source>Song %1 as shown: uploaded (140) and played (141).</source>
        <translation>Canción %1 tal como se ve: subida (140) y reproducida (141).</translation>
    </message>
</context>
<context>
    <name>SongFiles</name>
    <message>
        <source>Not a JSON file: %1 at offset %2</source>
        <translation>No es un archivo JSON: %1 en el desplazamiento %2</translation>
    </message>
    <message>
        <source>Not a song file: the top level is not an object</source>
        <translation>No es un archivo de canciones: el nivel superior no es un objeto</translation>
    </message>
    <message>
        <source>Not a song file: &quot;format&quot; is not &quot;%1&quot;</source>
        <translation>No es un archivo de canciones: &quot;format&quot; no es &quot;%1&quot;</translation>
    </message>
    <message>
        <source>Song file version %1 is not supported; only version %2 is</source>
        <translation>La versión %1 del archivo de canciones no es compatible; solo lo es la versión %2</translation>
    </message>
    <message>
        <source>Song file has no &quot;songs&quot; list</source>
        <translation>El archivo de canciones no tiene lista &quot;songs&quot;</translation>
    </message>
    <message>
        <source>Song %1: slot %2 is outside 0..%3 for this robot</source>
        <translation>Canción %1: la ranura %2 está fuera de 0..%3 para este robot</translation>
    </message>
    <message>
        <source>Song %1: slot %2 appears twice</source>
        <translation>Canción %1: la ranura %2 aparece dos veces</translation>
    </message>
    <message>
        <source>Song in slot %1 has no &quot;notes&quot; list</source>
        <translation>La canción de la ranura %1 no tiene lista &quot;notes&quot;</translation>
    </message>
    <message>
        <source>Song in slot %1 has %2 notes; a song has 1..%3</source>
        <translation>La canción de la ranura %1 tiene %2 notas; una canción tiene 1..%3</translation>
    </message>
    <message>
        <source>Slot %1, note %2: expected [note 0..127, duration 0..255], got %3</source>
        <translation>Ranura %1, nota %2: se esperaba [nota 0..127, duración 0..255], se obtuvo %3</translation>
    </message>
    <message>
        <source>Could not save %1: %2</source>
        <translation>No se pudo guardar %1: %2</translation>
    </message>
    <message>
        <source>Could not open %1: %2</source>
        <translation>No se pudo abrir %1: %2</translation>
    </message>
    <message>
        <source>Cannot transpose by %1: note %2 (%3) would become %4, outside %5..%6</source>
        <translation>No se puede transponer %1: la nota %2 (%3) pasaría a ser %4, fuera de %5..%6</translation>
    </message>
    <message>
        <source>Cannot scale durations by %1: note %2 would last %3/64 s; durations must stay within 1..255</source>
        <translation>No se pueden escalar las duraciones por %1: la nota %2 duraría %3/64 s; las duraciones deben estar entre 1..255</translation>
    </message>
    <message>
        <source>rest</source>
        <translation>silencio</translation>
    </message>
</context>
<context>
    <name>SongWave</name>
    <message>
        <source>Could not save %1: %2</source>
        <translation>No se pudo guardar %1: %2</translation>
    </message>
</context>
<context>
    <name>StopAllButton</name>
    <message>
        <source>STOP ALL  (Shift+Esc)</source>
        <translation>DETENER TODOS  (Mayús+Esc)</translation>
    </message>
    <message>
        <source>Stop every robot at once, whichever is selected: the window&apos;s robots and every robot on the broker.
Shift+Esc does the same from any window; Space or Esc stops the selected robot.</source>
        <translation>Detiene a la vez todos los robots, esté seleccionado el que esté: los de la ventana y todos los del broker.
Mayús+Esc hace lo mismo desde cualquier ventana; Espacio o Esc detiene el robot seleccionado.</translation>
    </message>
    <message>
        <source>Stop all robots</source>
        <translation>Detener todos los robots</translation>
    </message>
</context>
<context>
    <name>TeleopController</name>
    <message>
        <source>Not driving: no live data from the robot, so nobody could see it move. Wait until it streams.</source>
        <translation>No se mueve: no llegan datos en vivo del robot, nadie podría verlo moverse. Espere a que envíe datos.</translation>
    </message>
    <message>
        <source>Not driving: %1</source>
        <translation>No se mueve: %1</translation>
    </message>
    <message>
        <source>Not driving: the robot is in Passive mode and ignores motion. Press Enter Safe to drive.</source>
        <translation>No se mueve: el robot está en modo Passive e ignora el movimiento. Pulse «Pasar a Safe» para conducir.</translation>
    </message>
    <message>
        <source>Not driving: %1. Put it down on the floor to drive.</source>
        <translation>No se mueve: %1. Póngalo en el suelo para conducir.</translation>
    </message>
</context>
<context>
    <name>ValueGauge</name>
    <message>
        <source>OUT OF RANGE</source>
        <translation>FUERA DE RANGO</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <source>%1, out of range</source>
        <translation>%1, fuera de rango</translation>
    </message>
    <message>
        <source>%1, stale</source>
        <translation>%1, obsoleto</translation>
    </message>
    <message>
        <source>%1, unreliable: %2</source>
        <translation>%1, no fiable: %2</translation>
    </message>
</context>
<context>
    <name>mcap::Writer</name>
    <message>
        <source>cannot compress a chunk with %1</source>
        <translation>no se puede comprimir un bloque con %1</translation>
    </message>
</context>
<context>
    <name>oilink</name>
    <message>
        <source>%1 must be a whole number from %2 to %3, not %4.</source>
        <translation>%1 debe ser un número entero de %2 a %3, no %4.</translation>
    </message>
    <message>
        <source>%1 must be a number of at least 0.</source>
        <translation>%1 debe ser un número de al menos 0.</translation>
    </message>
</context>
<context>
    <name>oilink::ConnectionDoctor</name>
    <message>
        <source>%1 baud</source>
        <translation>%1 baudios</translation>
    </message>
    <message>
        <source>At %1 it answers.</source>
        <translation>A %1 responde.</translation>
    </message>
    <message>
        <source>At %1 it answers after Start (it was in Off mode).</source>
        <translation>A %1 responde tras Start (estaba en modo apagado).</translation>
    </message>
    <message numerus="yes">
        <source>At %1: %n byte(s) that make no sense.</source>
        <translation>
            <numerusform>A %1: %n byte sin sentido.</numerusform>
            <numerusform>A %1: %n bytes sin sentido.</numerusform>
        </translation>
    </message>
    <message>
        <source>At %1: nothing comes back, with or without Start.</source>
        <translation>A %1: no vuelve nada, con o sin Start.</translation>
    </message>
    <message>
        <source>Bytes come back, but at no baud do they make sense: a noisy cable, or a device that is not an Open Interface robot.</source>
        <translation>Vuelven bytes, pero a ninguna velocidad tienen sentido: un cable con ruido o un dispositivo que no es un robot Open Interface.</translation>
    </message>
    <message>
        <source>Nothing comes back: is the robot on and the cable plugged in? (A sleeping robot cannot be woken over this connection.)</source>
        <translation>No vuelve nada: ¿está el robot encendido y el cable conectado? (Un robot dormido no se puede despertar por esta conexión.)</translation>
    </message>
    <message>
        <source>At %1 it answers after the pulse.</source>
        <translation>A %1 responde tras el pulso.</translation>
    </message>
    <message>
        <source>2 s after the wake pulse, pulsed the BRC pin three times for 19200 baud.</source>
        <translation>2 s después del pulso de despertar, se pulsó el pin BRC tres veces para 19200 baudios.</translation>
    </message>
    <message>
        <source>At 19200 baud it answers after the three pulses.</source>
        <translation>A 19200 baudios responde tras los tres pulsos.</translation>
    </message>
    <message>
        <source>It answers Sensors 101: a Roomba 500 or a Create 2 (they answer alike).</source>
        <translation>Responde a Sensors 101: un Roomba 500 o un Create 2 (responden igual).</translation>
    </message>
    <message>
        <source>It has no packet group 101: a Create.</source>
        <translation>No tiene el grupo de paquetes 101: un Create.</translation>
    </message>
    <message>
        <source>The robot was asleep; a BRC pulse woke it.</source>
        <translation>El robot dormía; un pulso BRC lo despertó.</translation>
    </message>
    <message>
        <source>The robot was asleep; a BRC pulse woke it, and it talks at %1 baud.</source>
        <translation>El robot dormía; un pulso BRC lo despertó, y habla a %1 baudios.</translation>
    </message>
    <message>
        <source>After three BRC pulses the robot now talks at 19200 baud: set the baud to 19200.</source>
        <translation>Tras tres pulsos BRC el robot habla ahora a 19200 baudios: ajuste la velocidad a 19200.</translation>
    </message>
    <message>
        <source>Wrong baud: the robot answers at %1 baud, not %2.</source>
        <translation>Velocidad errónea: el robot responde a %1 baudios, no a %2.</translation>
    </message>
    <message>
        <source>The robot answers as a %1, not as the %2 the connection names.</source>
        <translation>El robot responde como %1, no como el %2 que indica la conexión.</translation>
    </message>
    <message>
        <source>Roomba 500 or Create 2</source>
        <translation>Roomba 500 o Create 2</translation>
    </message>
    <message>
        <source>The robot answers at %1 as a %2.</source>
        <translation>El robot responde a %1 como %2.</translation>
    </message>
    <message>
        <source>Bytes come back, but they make no sense. This connection cannot change the bridge&apos;s rate: the robot may talk at another baud than the bridge&apos;s serial port (set the bridge to the robot&apos;s rate, or use its RFC 2217 telnet mode so that each rate can be tried), or the device is not an Open Interface robot.</source>
        <translation>Llegan bytes, pero no tienen sentido. Esta conexión no puede cambiar la velocidad del puente: puede que el robot hable a otros baudios que el puerto serie del puente (ajuste el puente a la velocidad del robot o use su modo telnet RFC 2217 para poder probar cada velocidad), o el dispositivo no es un robot Open Interface.</translation>
    </message>
    <message>
        <source>The robot answers at %1 as a Roomba 500 or a Create 2. The two answer alike but read their wheel encoders the other way round: name which it is.</source>
        <translation>El robot responde a %1 como un Roomba 500 o un Create 2. Los dos responden igual, pero leen sus codificadores de rueda al revés: indique cuál es.</translation>
    </message>
    <message>
        <source>Pulsed the BRC pin on the wake line (%1) to wake the robot.</source>
        <translation>Se pulsó el pin BRC por la línea de despertar (%1) para despertar al robot.</translation>
    </message>
    <message>
        <source>Silent so far; a slow robot takes up to 2 s to wake: asking again once it has had that time.</source>
        <translation>Sin respuesta por ahora; un robot lento tarda hasta 2 s en despertar: se vuelve a preguntar cuando haya tenido ese tiempo.</translation>
    </message>
    <message>
        <source>Still silent: pulsed the other line (%1) instead.</source>
        <translation>Sigue sin responder: se pulsó la otra línea (%1) en su lugar.</translation>
    </message>
    <message>
        <source>No line wakes it: still silent after BRC pulses on RTS and on DTR. The cable may not carry the BRC pin (press Clean to wake the robot), or the robot is off or unplugged, or asleep on its dock with firmware before release-3.8.2 / release-stm32-3.7.7, which does not wake by BRC there (lift it off the dock, or press Clean).</source>
        <translation>Ninguna línea lo despierta: sigue sin responder tras pulsos BRC por RTS y por DTR. Puede que el cable no lleve el pin BRC (pulse Clean para despertar al robot), o el robot está apagado o desconectado, o duerme en su base con un firmware anterior a release-3.8.2 / release-stm32-3.7.7, que allí no despierta por BRC (levántelo de la base o pulse Clean).</translation>
    </message>
    <message>
        <source>The wake pulse works on %1, not %2: the cable carries the robot&apos;s BRC pin on %1. Set the wake line to %1 (--brc-line %3).</source>
        <translation>El pulso de despertar funciona por %1, no por %2: el cable lleva el pin BRC del robot en %1. Ponga la línea de despertar en %1 (--brc-line %3).</translation>
    </message>
    <message>
        <source>At %1 the robot prints text: &quot;%2&quot;.</source>
        <translation>A %1 el robot escribe texto: &quot;%2&quot;.</translation>
    </message>
    <message>
        <source>At %1 it prints text but does not answer.</source>
        <translation>A %1 escribe texto pero no responde.</translation>
    </message>
    <message>
        <source>At %1 the robot prints its charging status (&quot;%2&quot;): the baud and the cable are right, and it is a Roomba on its dock. It does not answer there: asleep on its dock (firmware before release-3.8.2 / release-stm32-3.7.7 does not wake by BRC there). Press Clean, or lift it off the dock.</source>
        <translation>A %1 el robot escribe su estado de carga (&quot;%2&quot;): los baudios y el cable son correctos, y es un Roomba en su base. Allí no responde: duerme en su base (el firmware anterior a release-3.8.2 / release-stm32-3.7.7 no despierta por BRC allí). Pulsa Clean, o levántalo de la base.</translation>
    </message>
    <message>
        <source>It prints its charging status (&quot;%1&quot;): it is on its dock.</source>
        <translation>Escribe su estado de carga (&quot;%1&quot;): está en su base.</translation>
    </message>
    <message>
        <source>It answers Sensors 0 but has no packet 35 (OI mode): a Roomba 400 series, which speaks the older SCI (2005).</source>
        <translation>Responde a Sensors 0 pero no tiene el paquete 35 (modo OI): un Roomba de la serie 400, que habla el SCI, más antiguo (2005).</translation>
    </message>
    <message>
        <source>It printed &quot;%1&quot;: the text a Roomba 400 prints as it starts up, not a charging status.</source>
        <translation>Escribió &quot;%1&quot;: el texto que escribe un Roomba 400 al arrancar, no un estado de carga.</translation>
    </message>
</context>
<context>
    <name>oilink::ReplayTransport</name>
    <message>
        <source>replay of %1</source>
        <translation>reproducción de %1</translation>
    </message>
</context>
<context>
    <name>oilink::RobotLink</name>
    <message>
        <source>bunched link (frames every %1 s)</source>
        <translation>enlace a ráfagas (tramas cada %1 s)</translation>
    </message>
</context>
<context>
    <name>oilink::RobotLinkThread</name>
    <message>
        <source>not connected: the command was not sent</source>
        <translation>sin conexión: la orden no se envió</translation>
    </message>
    <message>
        <source>not connected: the sensor query was not sent</source>
        <translation>sin conexión: la consulta de sensores no se envió</translation>
    </message>
    <message>
        <source>not connected: Show Script was not sent</source>
        <translation>sin conexión: Show Script no se envió</translation>
    </message>
    <message>
        <source>not connected: there is nothing to check</source>
        <translation>sin conexión: no hay nada que comprobar</translation>
    </message>
    <message>
        <source>not connected: there is nothing to wake</source>
        <translation>sin conexión: no hay nada que despertar</translation>
    </message>
</context>
<context>
    <name>oilink::SerialTransport</name>
    <message>
        <source>%1: no such port</source>
        <translation>%1: no existe el puerto</translation>
    </message>
    <message>
        <source>%1: permission denied (is your user in the dialout group?)</source>
        <translation>%1: permiso denegado (¿está su usuario en el grupo dialout?)</translation>
    </message>
    <message>
        <source>%1: port busy (another program has it open)</source>
        <translation>%1: puerto ocupado (otro programa lo tiene abierto)</translation>
    </message>
    <message>
        <source>%1: cannot open: %2</source>
        <translation>%1: no se puede abrir: %2</translation>
    </message>
    <message>
        <source>the port went away</source>
        <translation>el puerto ha desaparecido</translation>
    </message>
    <message>
        <source>%1: the port has no RTS or DTR line to pulse the BRC pin with</source>
        <translation>%1: el puerto no tiene línea RTS ni DTR para pulsar el pin BRC</translation>
    </message>
</context>
<context>
    <name>oilink::TcpTransport</name>
    <message>
        <source>connection refused</source>
        <translation>conexión rechazada</translation>
    </message>
    <message>
        <source>no such host</source>
        <translation>no existe el equipo</translation>
    </message>
    <message>
        <source>no answer (timed out)</source>
        <translation>sin respuesta (tiempo agotado)</translation>
    </message>
    <message>
        <source>network unreachable</source>
        <translation>red inaccesible</translation>
    </message>
    <message>
        <source>%1: the bridge closed the connection</source>
        <translation>%1: el puente cerró la conexión</translation>
    </message>
    <message>
        <source>%1: connection lost (%2)</source>
        <translation>%1: conexión perdida (%2)</translation>
    </message>
    <message>
        <source>%1: no answer (timed out)</source>
        <translation>%1: sin respuesta (tiempo agotado)</translation>
    </message>
    <message>
        <source>%1: the bridge closed the connection: %2</source>
        <translation>%1: el puente cerró la conexión: %2</translation>
    </message>
    <message>
        <source>%1: raw TCP carries no modem lines, so it cannot wake the robot or keep it awake</source>
        <translation>%1: el TCP sin procesar no lleva líneas de módem, así que no puede despertar al robot ni mantenerlo despierto</translation>
    </message>
</context>
<context>
    <name>oilink::Transport</name>
    <message>
        <source>%1 cannot reach the robot&apos;s BRC pin</source>
        <translation>%1 no llega al pin BRC del robot</translation>
    </message>
    <message>
        <source>%1: the wake line is set to none, so the cable is taken to have no BRC wire</source>
        <translation>%1: la línea de despertar está en ninguna, así que se toma el cable como sin hilo BRC</translation>
    </message>
</context>
</TS>

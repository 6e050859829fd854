<?xml version='1.0' encoding='utf-8'?>
<TS version="2.1" language="de_DE">
<context>
    <name>Diagnostic</name>
    <message>
        <location filename="../../src/core/common/diagnostic_catalogue.cpp" line="+20" />
        <source>must be a finite number (got %1)</source>
        <translation>muss eine endliche Zahl sein (ist %1)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>magnitude must be at most 1e6 mm (got %1)</source>
        <translation>Betrag darf höchstens 10⁶ mm sein (ist %1)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>must be between %1 and %2%3 (got %4)</source>
        <translation>muss zwischen %1 und %2%3 liegen (ist %4)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>must be at least %1 mm (got %2): a smaller circle or step is below the precision of the joints</source>
        <translation>muss mindestens %1 mm sein (ist %2): ein kleinerer Kreis oder Schritt liegt unter der Genauigkeit der Übergänge</translation>
    </message>
    <message>
        <location line="+3" />
        <source>must be &gt; 0 (got %1)</source>
        <translation>muss &gt; 0 sein (ist %1)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>must not be 0 (its sign gives the turning direction)</source>
        <translation>darf nicht 0 sein (das Vorzeichen gibt die Drehrichtung an)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>magnitude must be between %1 and %2%3 (got %4)</source>
        <translation>Betrag muss zwischen %1 und %2%3 liegen (ist %4)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>must have at least one segment</source>
        <translation>muss mindestens ein Segment haben</translation>
    </message>
    <message>
        <location line="+2" />
        <source>must be a finite angle of magnitude at most 1e6° (got %1)</source>
        <translation>muss ein endlicher Winkel mit einem Betrag von höchstens 10⁶° sein (ist %1)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>must be greater than %1 %2° (got %3°)</source>
        <translation>muss größer als %1 %2° sein (ist %3°)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>at %1° the follower ray only grazes the curve (it must cross it at an angle of at least %2 rad, or the follower would need an unbounded speed); the window must end before it</source>
        <translation>bei %1° streift der Strahl des Stößels die Kurve nur (er muss sie unter einem Winkel von mindestens %2 rad schneiden, sonst bräuchte der Stößel eine unbegrenzte Geschwindigkeit); das Fenster muss vorher enden</translation>
    </message>
    <message>
        <location line="+5" />
        <source>window %1° .. %2° disagrees with the polar angles of from/to (%3° .. %4°)</source>
        <translation>das Fenster %1° .. %2° passt nicht zu den Polarwinkeln von Anfangs- und Endpunkt der Geraden (%3° .. %4°)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>window %1° .. %2° disagrees with the polar angles of its end points (%3° .. %4°)</source>
        <translation>das Fenster %1° .. %2° passt nicht zu den Polarwinkeln der Endpunkte der Kurve (%3° .. %4°)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>must differ from `from` (the line has no length)</source>
        <translation>muss sich vom Anfangspunkt unterscheiden (die Gerade hat keine Länge)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the line passes through the rotation centre, so the follower ray meets it at no angle or at every point</source>
        <translation>die Gerade geht durch das Drehzentrum, daher trifft der Strahl des Stößels sie unter keinem Winkel oder in jedem Punkt</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the line runs clockwise around the rotation centre (from %1° to %2°); swap `from` and `to`</source>
        <translation>die Gerade läuft im Uhrzeigersinn um das Drehzentrum (von %1° bis %2°); Anfangs- und Endpunkt tauschen</translation>
    </message>
    <message>
        <location line="+4" />
        <source>an end point lies on the rotation centre</source>
        <translation>ein Endpunkt liegt im Drehzentrum</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the curve runs clockwise around the rotation centre (from %1° to %2°); reverse its points</source>
        <translation>die Kurve läuft im Uhrzeigersinn um das Drehzentrum (von %1° bis %2°); ihre Punkte umkehren</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the follower ray meets the curve %1 times at %2°; inside its window it must meet it exactly once</source>
        <translation>der Strahl des Stößels trifft die Kurve bei %2° %1-mal; innerhalb ihres Fensters muss er sie genau einmal treffen</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the rotation centre lies inside this circle, so the inner intersection is behind the follower (r &lt;= 0); use "outer"</source>
        <translation>das Drehzentrum liegt in diesem Kreis, daher liegt der innere Schnittpunkt hinter dem Stößel (r ≤ 0); den Zweig „außen“ wählen</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the follower ray misses the circle inside the window %1° .. %2°; it meets it only for phi in %3° .. %4°</source>
        <translation>der Strahl des Stößels verfehlt den Kreis im Fenster %1° .. %2°; er trifft ihn nur für φ in %3° .. %4°</translation>
    </message>
    <message>
        <location line="+4" />
        <source>gap of %1° between %2 %3 and %4 %5</source>
        <translation>Lücke von %1° zwischen %2 %3° und %4 %5°</translation>
    </message>
    <message>
        <location line="+2" />
        <source>overlap of %1° between %2 %3 and %4 %5</source>
        <translation>Überlappung von %1° zwischen %2 %3° und %4 %5°</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the windows cover %1° (from %2° to %3°); they must cover exactly one turn, 360°</source>
        <translation>die Fenster überdecken %1° (von %2° bis %3°); sie müssen genau eine Umdrehung überdecken, 360°</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the segments do not meet at %1°: gap of %2 mm (at most 1e-06 mm allowed)</source>
        <translation>die Segmente treffen sich bei %1° nicht: Lücke von %2 mm (höchstens 10⁻⁶ mm erlaubt)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>a flat face moves only translating (math.md §7); use a knife or a roller on an oscillating arm</source>
        <translation>ein Flachstößel bewegt sich nur geradgeführt; auf einem Schwinghebel eine Spitze oder eine Rolle verwenden</translation>
    </message>
    <message>
        <location line="+4" />
        <source>must be smaller than the radius %1 mm of the concave arc %2 (got %3 mm): the roller cannot enter it</source>
        <translation>muss kleiner sein als der Radius %1 mm des konkaven Bogens %2 (ist %3 mm): die Rolle passt nicht hinein</translation>
    </message>
    <message>
        <location line="+4" />
        <source>must be between 16 and 10000000 (got %1)</source>
        <translation>muss zwischen 16 und 10000000 liegen (ist %1)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>must list 2 or 3 axes (got %1)</source>
        <translation>muss 2 oder 3 Achsen angeben (sind %1)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 needs a joint between two segments (the contour has %2)</source>
        <translation>%1 braucht einen Übergang zwischen zwei Segmenten (die Kontur hat %2)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>there is no joint %1: joints are numbered 0 .. %2</source>
        <translation>es gibt keinen Übergang %1: die Übergänge sind von 0 bis %2 nummeriert</translation>
    </message>
    <message>
        <location line="+2" />
        <source>must be after %1°, where this segment starts (got %2°)</source>
        <translation>muss nach %1° liegen, wo dieses Segment beginnt (ist %2°)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>must be at most 360° (got %1°)</source>
        <translation>darf höchstens 360° sein (ist %1°)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>a dwell keeps the lift it starts with (%1), got %2</source>
        <translation>eine Rast behält den Hub, mit dem sie beginnt (%1), ist aber %2</translation>
    </message>
    <message>
        <location line="+2" />
        <source>must differ from the lift it starts with (%1) for %2; a stretch without motion is a dwell</source>
        <translation>muss sich für %2 vom Hub am Anfang (%1) unterscheiden; ein Abschnitt ohne Bewegung ist eine Rast</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the last segment must end at 360° (got %1°)</source>
        <translation>das letzte Segment muss bei 360° enden (ist %1°)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the motion must return to the start: the last lift must be 0 (got %1)</source>
        <translation>die Bewegung muss zum Anfang zurückkehren: der letzte Hub muss 0 sein (ist %1)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the velocity jumps from %1 to %2 per degree</source>
        <translation>die Geschwindigkeit springt von %1 auf %2 pro Grad</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the acceleration jumps from %1 to %2 per degree²</source>
        <translation>die Beschleunigung springt von %1 auf %2 pro Grad²</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the velocity jumps from %1 to %2 per degree; the acceleration jumps from %3 to %4 per degree²</source>
        <translation>die Geschwindigkeit springt von %1 auf %2 pro Grad; die Beschleunigung springt von %3 auf %4 pro Grad²</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 cannot meet the %2 at its %3: its velocity there is %4 per degree, the neighbour's %5 (Suggest picks a law that can)</source>
        <translation>%1 kann die Randbedingung %2 an seinem %3 nicht erfüllen: seine Geschwindigkeit dort ist %4 je Grad, die des Nachbarn %5 (Vorschlagen wählt ein Gesetz, das es kann)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>b + d must be at most 1, the constant acceleration taking the rest (got %1 + %2)</source>
        <translation>b + d darf höchstens 1 sein, den Rest nimmt die konstante Beschleunigung (erhalten %1 + %2)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>a motion table needs at least 2 points (got %1)</source>
        <translation>eine Bewegungstabelle braucht mindestens 2 Punkte (erhalten %1)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>a motion table takes at most %1 points (got %2)</source>
        <translation>eine Bewegungstabelle fasst höchstens %1 Punkte (erhalten %2)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>point %1: x must be greater than the point before's (%2), got %3</source>
        <translation>Punkt %1: x muss größer sein als beim Punkt davor (%2), erhalten %3</translation>
    </message>
    <message>
        <location line="+3" />
        <source>must run from (0, 0) to (1, 1), normalised (got (%1, %2) to (%3, %4))</source>
        <translation>muss normiert von (0, 0) bis (1, 1) laufen (erhalten (%1, %2) bis (%3, %4))</translation>
    </message>
    <message>
        <location line="+3" />
        <source>must hold x y or x y dy/dx (got %1 columns)</source>
        <translation>muss x y oder x y dy/dx enthalten (erhalten %1 Spalten)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>is not a number: "%1"</source>
        <translation>ist keine Zahl: „%1“</translation>
    </message>
    <message>
        <location line="+2" />
        <source>no spline runs through these points (their spacing is too uneven)</source>
        <translation>durch diese Punkte läuft kein Spline (ihre Abstände sind zu ungleich)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>missing</source>
        <translation>fehlt</translation>
    </message>
    <message>
        <location line="+1" />
        <source>unknown key</source>
        <translation>unbekannter Schlüssel</translation>
    </message>
    <message>
        <location line="+1" />
        <source>must be %1 (got %2)</source>
        <translation>muss %1 sein (ist %2)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>must be an array [x, y] of two numbers (got %1 elements)</source>
        <translation>muss ein Array [x, y] aus zwei Zahlen sein (hat %1 Elemente)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>must be %1 or %2 (got "%3")</source>
        <translation>muss %1 oder %2 sein (ist „%3“)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>must be %1 (got "%2")</source>
        <translation>muss %1 sein (ist „%2“)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>unknown segment type "%1" (expected "arc", "line", "bezier" or "hermite")</source>
        <translation>unbekannter Segmenttyp „%1“ (erwartet „arc“, „line“, „bezier“ oder „hermite“)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>unknown law "%1" (expected one of %2)</source>
        <translation>unbekanntes Bewegungsgesetz „%1“ (erwartet eines von %2)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>must give exactly one of omega_rad_s, rpm, period_s (got %1)</source>
        <translation>muss genau eines von omega_rad_s, rpm, period_s angeben (sind %1)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>must be a whole number between 16 and 10000000 (got %1)</source>
        <translation>muss eine ganze Zahl zwischen 16 und 10000000 sein (ist %1)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>this file has format version %1; this Camwright reads version 1 only — open it with a newer Camwright</source>
        <translation>diese Datei hat die Formatversion %1; dieses Camwright liest nur Version 1 – bitte mit einem neueren Camwright öffnen</translation>
    </message>
    <message>
        <location line="+3" />
        <source>must be 1 (got %1)</source>
        <translation>muss 1 sein (ist %1)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>must be an array of four points [x, y]</source>
        <translation>muss ein Array aus vier Punkten [x, y] sein</translation>
    </message>
    <message>
        <location line="+1" />
        <source>duplicated key</source>
        <translation>doppelter Schlüssel</translation>
    </message>
    <message>
        <location line="+2" />
        <source>number %1 is too large for a double</source>
        <translation>die Zahl %1 ist zu groß für eine Gleitkommazahl (double)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1</source>
        <translation>kein gültiges JSON: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>nesting deeper than %1 levels</source>
        <translation>Verschachtelung tiefer als %1 Ebenen</translation>
    </message>
    <message>
        <location line="+2" />
        <source>a NUL byte (at byte offset %1): a project file is text</source>
        <translation>ein NUL-Byte (bei Byte-Position %1): eine Projektdatei ist Text</translation>
    </message>
    <message>
        <location line="+1" />
        <source>not valid JSON</source>
        <translation>kein gültiges JSON</translation>
    </message>
    <message>
        <location line="+2" />
        <source>expected %1 or %2 (got %3 values)</source>
        <translation>erwartet %1 oder %2 (%3 Werte erhalten)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>expected %1 (got %2 values)</source>
        <translation>erwartet %1 (%2 Werte erhalten)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 must be a finite number (got "%2")</source>
        <translation>%1 muss eine endliche Zahl sein (ist „%2“)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the contour is not valid, so the joint cannot be rounded</source>
        <translation>die Kontur ist nicht gültig, daher kann der Übergang nicht verrundet werden</translation>
    </message>
    <message>
        <location line="+2" />
        <source>fillets join arcs and lines; %1 is neither</source>
        <translation>Verrundungen verbinden Bögen und Geraden; %1 ist keins von beiden</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the segments already meet tangentially (their tangents differ by %1°, at most %2° counts as tangent); there is no corner to round</source>
        <translation>die Segmente treffen sich bereits tangential (ihre Tangenten unterscheiden sich um %1°, bis %2° gilt als tangential); es gibt keine Ecke zu verrunden</translation>
    </message>
    <message>
        <location line="+4" />
        <source>radius %1 mm does not fit: fillets join arcs and lines; %2 is neither</source>
        <translation>Radius %1 mm passt nicht: Verrundungen verbinden Bögen und Geraden; %2 ist keins von beiden</translation>
    </message>
    <message>
        <location line="+3" />
        <source>radius %1 mm does not fit: the segments already meet tangentially (their tangents differ by %2°, at most %3° counts as tangent); there is no corner to round</source>
        <translation>Radius %1 mm passt nicht: die Segmente treffen sich bereits tangential (ihre Tangenten unterscheiden sich um %2°, bis %3° gilt als tangential); es gibt keine Ecke zu verrunden</translation>
    </message>
    <message>
        <location line="+5" />
        <source>no fillet radius of at least %1 mm fits at this joint (%2)</source>
        <translation>an diesem Übergang passt kein Verrundungsradius von mindestens %1 mm (%2)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>radius %1 mm does not fit: no fillet radius of at least %2 mm fits at this joint (%3)</source>
        <translation>Radius %1 mm passt nicht: an diesem Übergang passt kein Verrundungsradius von mindestens %2 mm (%3)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>radius %1 mm is too small: a fillet radius is at least %2 mm, the smallest radius a project holds</source>
        <translation>Radius %1 mm ist zu klein: ein Verrundungsradius beträgt mindestens %2 mm, den kleinsten Radius, den ein Projekt fasst</translation>
    </message>
    <message>
        <location line="+4" />
        <source>radius %1 mm must be a number &gt; 0: radii below %2 mm fit</source>
        <translation>Radius %1 mm muss eine Zahl &gt; 0 sein: Radien unter %2 mm passen</translation>
    </message>
    <message>
        <location line="+2" />
        <source>radius %1 mm is too large: only radii below %2 mm fit (%3)</source>
        <translation>Radius %1 mm ist zu groß: nur Radien unter %2 mm passen (%3)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>radius %1 mm does not fit (%2), although most radii below %3 mm do</source>
        <translation>Radius %1 mm passt nicht (%2), obwohl die meisten Radien unter %3 mm passen</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the tangent point would leave %1</source>
        <translation>der Berührpunkt würde %1 verlassen</translation>
    </message>
    <message>
        <location line="+2" />
        <source>no circle of that radius touches both neighbours inside the corner</source>
        <translation>kein Kreis dieses Radius berührt beide Nachbarn innerhalb der Ecke</translation>
    </message>
    <message>
        <location line="+3" />
        <source>no larger circle touches both neighbours inside the corner</source>
        <translation>kein größerer Kreis berührt beide Nachbarn innerhalb der Ecke</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the follower ray would not meet the fillet arc exactly once: it would pass the rotation centre or turn back as seen from it</source>
        <translation>der Strahl des Stößels träfe den Verrundungsbogen nicht genau einmal: er ginge durch das Drehzentrum oder liefe, von dort gesehen, zurück</translation>
    </message>
    <message>
        <location line="+3" />
        <source>radii are limited to 1e6 mm</source>
        <translation>Radien sind auf 10⁶ mm begrenzt</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the roller radius %1 mm is not smaller than this concave arc's radius %2 mm: the roller cannot follow it</source>
        <translation>der Rollenradius %1 mm ist nicht kleiner als der Radius %2 mm dieses konkaven Bogens: die Rolle kann ihm nicht folgen</translation>
    </message>
    <message>
        <location line="+4" />
        <source>is inside the cam: the pivot turns on a circle of radius %1 mm round the cam centre, but the profile reaches %2 mm at %3°; move it farther out</source>
        <translation>liegt in der Kurvenscheibe: der Drehpunkt läuft auf einem Kreis mit Radius %1 mm um die Mitte der Kurvenscheibe, aber das Profil reicht bei %3° bis %2 mm; ihn weiter nach außen legen</translation>
    </message>
    <message>
        <location line="+4" />
        <source>is too short: at %1° the cam is %2 mm from the pivot, and %3 reaches only %4 mm</source>
        <translation>ist zu kurz: bei %1° ist die Kurvenscheibe %2 mm vom Drehpunkt entfernt, und %3 reicht nur %4 mm weit</translation>
    </message>
    <message>
        <location line="+4" />
        <source>is too long: at %1° %2 passes beyond the whole cam (at most %3 mm from the pivot)</source>
        <translation>ist zu lang: bei %1° reicht %2 über die ganze Kurvenscheibe hinaus (sie ist höchstens %3 mm vom Drehpunkt entfernt)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>does not let %1 touch the cam at %2° (no contact on the chosen side of the arm)</source>
        <translation>lässt %1 die Kurvenscheibe bei %2° nicht berühren (kein Kontakt auf der gewählten Seite des Hebels)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the tool radius %1 mm is larger than this curve's tightest concave radius %2 mm: the offset path degenerates</source>
        <translation>der Werkzeugradius %1 mm ist größer als der engste konkave Radius %2 mm dieser Kurve: die versetzte Bahn entartet</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the tool radius %1 mm is not smaller than the radius %2 mm of this concave arc: the offset path degenerates</source>
        <translation>der Werkzeugradius %1 mm ist nicht kleiner als der Radius %2 mm dieses konkaven Bogens: die versetzte Bahn entartet</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the offset segments do not meet at this corner</source>
        <translation>die versetzten Segmente treffen sich an dieser Ecke nicht</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the tool radius %1 mm is too large here: at its concave corners the offset of this segment would have to be trimmed beyond its ends</source>
        <translation>der Werkzeugradius %1 mm ist hier zu groß: an seinen konkaven Ecken müsste die versetzte Bahn dieses Segments über seine Enden hinaus gekürzt werden</translation>
    </message>
    <message>
        <location line="+4" />
        <source>undercuts the groove's outer flank: for a roller of %1 mm with %2 mm clearance this concave stretch of radius %3 mm must be wider than twice the roller radius plus the clearance</source>
        <translation>hinterschneidet die äußere Flanke der Nut: für eine Rolle von %1 mm mit %2 mm Spiel muss dieser hohle Abschnitt mit Radius %3 mm weiter sein als der doppelte Rollenradius plus das Spiel</translation>
    </message>
    <message>
        <location line="+5" />
        <source>a groove needs a roller follower: a knife or a flat face cannot run in a groove; choose a roller or the spring closure</source>
        <translation>eine Nut braucht einen Rollenstößel: eine Schneide oder ein Flachstößel kann nicht in einer Nut laufen; wählen Sie eine Rolle oder den Kraftschluss durch eine Feder</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the tool radius %1 mm is wider than the groove: at most half its width, %2 mm (the roller radius plus half the clearance)</source>
        <translation>der Werkzeugradius %1 mm ist breiter als die Nut: höchstens ihre halbe Breite, %2 mm (Rollenradius plus halbes Spiel)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the tool radius %1 mm is too small to clear the groove in a roughing pass on its centre line and a finishing pass along each flank: at least %2 mm (a sixth of its width)</source>
        <translation>der Werkzeugradius %1 mm ist zu klein, um die Nut mit einem Schruppgang auf ihrer Mittellinie und einem Schlichtgang an jeder Flanke auszuräumen: mindestens %2 mm (ein Sechstel ihrer Breite)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>a groove is milled on computed tool-centre paths: a controller's cutter compensation (G41/G42) cannot follow both flanks</source>
        <translation>eine Nut wird auf berechneten Werkzeugmittelpunktbahnen gefräst: die Fräserradiuskorrektur einer Steuerung (G41/G42) kann nicht beiden Flanken folgen</translation>
    </message>
    <message>
        <location line="+4" />
        <source>a conjugate pair needs a roller follower: its second roller runs on the same line (a yoke) or on a second arm of the same pivot (a bell crank)</source>
        <translation>ein Kurvenpaar braucht einen Rollenstößel: Seine zweite Rolle läuft auf derselben Geraden (ein Joch) oder an einem zweiten Arm am selben Drehpunkt (ein Winkelhebel)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>must put the second roller beyond the cam centre at every angle: at %1° its centre is only %2 mm behind it</source>
        <translation>muss die zweite Rolle bei jedem Winkel jenseits der Scheibenmitte halten: bei %1° liegt ihr Mittelpunkt nur %2 mm hinter ihr</translation>
    </message>
    <message>
        <location line="+4" />
        <source>must let the second plate turn round the cam centre with the cam: at %1° the second roller moves backwards round it or reaches across it</source>
        <translation>muss die zweite Scheibe mit der Kurvenscheibe um deren Mitte laufen lassen: bei %1° läuft die zweite Rolle rückwärts um sie oder reicht über sie hinweg</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the second roller of %1 mm is wider than its path's bend at %2°: the second plate would fold over</source>
        <translation>die zweite Rolle von %1 mm ist breiter als die Krümmung ihrer Bahn bei %2°: die zweite Scheibe würde sich überschlagen</translation>
    </message>
    <message>
        <location line="+4" />
        <source>must be larger than the inner land radius %1 mm (got %2 mm): the groove runs between the two</source>
        <translation>muss größer sein als der innere Stegradius %1 mm (angegeben %2 mm): die Nut verläuft zwischen beiden</translation>
    </message>
    <message>
        <location line="+4" />
        <source>must be a finite length of at least %1 mm (got %2)</source>
        <translation>muss eine endliche Länge von mindestens %1 mm sein (ist %2)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 mm makes %2 steps on this %3 mm path; the seed method takes at most %4: a step of at least %5 mm</source>
        <translation>%1 mm ergibt %2 Schritte auf dieser %3 mm langen Bahn; das Ausgangsverfahren nimmt höchstens %4: eine Schrittweite von mindestens %5 mm</translation>
    </message>
    <message>
        <location line="+4" />
        <source>no acceleration limit for the %1 axis, along which the path moves (segment %2): without one its speed would be unbounded and its time 0</source>
        <translation>keine Beschleunigungsgrenze für die %1-Achse, entlang der die Bahn fährt (Segment %2): ohne sie wäre die Geschwindigkeit unbegrenzt und die Zeit 0</translation>
    </message>
    <message>
        <location line="+3" />
        <source>is empty</source>
        <translation>ist leer</translation>
    </message>
    <message>
        <location line="+2" />
        <source>coordinates must be finite, at most 1e6 mm, and the bulge finite</source>
        <translation>die Koordinaten müssen endlich und höchstens 10⁶ mm sein, die Wölbung endlich</translation>
    </message>
    <message>
        <location line="+3" />
        <source>a path needs at least two points</source>
        <translation>eine Bahn braucht mindestens zwei Punkte</translation>
    </message>
    <message>
        <location line="+1" />
        <source>repeats the previous point</source>
        <translation>wiederholt den vorigen Punkt</translation>
    </message>
    <message>
        <location line="+2" />
        <source>an arc (bulge %1) must keep its height, but z goes from %2 to %3</source>
        <translation>ein Bogen (Bulge %1) muss seine Höhe halten, aber z geht von %2 auf %3</translation>
    </message>
    <message>
        <location line="+3" />
        <source>an arc needs two distinct points in the XY plane</source>
        <translation>ein Bogen braucht zwei verschiedene Punkte in der XY-Ebene</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the arc (bulge %1) reaches %2 mm from the origin; a path must stay within %3 mm</source>
        <translation>der Bogen (Bulge %1) reicht %2 mm vom Ursprung weg; eine Bahn muss innerhalb von %3 mm bleiben</translation>
    </message>
    <message>
        <location line="+4" />
        <source>a tangent line joins two arcs; %1 is %2</source>
        <translation>eine Tangente verbindet zwei Bögen; %1 ist %2</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 is not a circle (its radius must be a finite number &gt; 0, its centre finite)</source>
        <translation>%1 ist kein Kreis (sein Radius muss eine endliche Zahl &gt; 0 sein, sein Mittelpunkt endlich)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>both arcs lie on the same circle, so they already meet tangentially: no line fits between them</source>
        <translation>beide Bögen liegen auf demselben Kreis und treffen sich daher bereits tangential: keine Gerade passt dazwischen</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the circle of %1 lies inside that of %2, so the two circles have no common tangent</source>
        <translation>der Kreis von %1 liegt in dem von %2, daher haben die beiden Kreise keine gemeinsame Tangente</translation>
    </message>
    <message>
        <location line="+3" />
        <source>no tangent line fits: %1</source>
        <translation>keine Tangente passt: %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the circles touch at (%1, %2): the arcs can meet there directly, without a line</source>
        <translation>die Kreise berühren sich in (%1; %2): die Bögen können sich dort direkt treffen, ohne Gerade</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 from (%2, %3) on %4 to (%5, %6) on %7 runs clockwise around the rotation centre (its polar angle would not grow from %4 to %7)</source>
        <translation>%1 von (%2; %3) auf %4 nach (%5; %6) auf %7 läuft im Uhrzeigersinn um das Drehzentrum (ihr Polarwinkel würde von %4 bis %7 nicht wachsen)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1 from (%2, %3) on %4 to (%5, %6) on %7 touches %8 on the near side of its circle, but the arc follows the far side (outer branch)</source>
        <translation>%1 von (%2; %3) auf %4 nach (%5; %6) auf %7 berührt %8 auf der nahen Seite seines Kreises, aber der Bogen folgt der fernen Seite (Zweig „außen“)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1 from (%2, %3) on %4 to (%5, %6) on %7 touches %8 on the far side of its circle, but the arc follows the near side (inner branch)</source>
        <translation>%1 von (%2; %3) auf %4 nach (%5; %6) auf %7 berührt %8 auf der fernen Seite seines Kreises, aber der Bogen folgt der nahen Seite (Zweig „innen“)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>with %1 from (%2, %3) on %4 to (%5, %6) on %7 the window of %4 would be empty: its end would move onto its start %8°</source>
        <translation>nähme man %1 von (%2; %3) auf %4 nach (%5; %6) auf %7, wäre das Fenster von %4 leer: sein Ende rückte auf seinen Anfang %8°</translation>
    </message>
    <message>
        <location line="+4" />
        <source>with %1 from (%2, %3) on %4 to (%5, %6) on %7 the window of %7 would be empty or reversed: its start would move to %8°, not before its end %9°</source>
        <translation>nähme man %1 von (%2; %3) auf %4 nach (%5; %6) auf %7, wäre das Fenster von %7 leer oder umgekehrt: sein Anfang rückte auf %8°, nicht vor sein Ende %9°</translation>
    </message>
    <message>
        <location line="+3" />
        <source>has no segment to continue</source>
        <translation>hat kein Segment, das sich fortsetzen ließe</translation>
    </message>
    <message>
        <location line="+2" />
        <source>there is no %1: rows are 0 .. %2</source>
        <translation>es gibt kein %1: die Zeilen sind 0 .. %2</translation>
    </message>
    <message>
        <location line="+2" />
        <source>a contour of one segment must be a circle; %1 is %2</source>
        <translation>eine Kontur aus einem Segment muss ein Kreis sein; %1 ist %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 is not a circle</source>
        <translation>%1 ist kein Kreis</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the follower ray at the end %1° of %2 misses its circle, so it has no end point</source>
        <translation>der Strahl des Stößels am Ende %1° von %2 verfehlt dessen Kreis, daher hat es keinen Endpunkt</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 has no direction at its end point</source>
        <translation>%1 hat an seinem Endpunkt keine Richtung</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 does not run counter-clockwise around the rotation centre at its end point (%2, %3) (its polar angle does not grow there)</source>
        <translation>%1 läuft an seinem Endpunkt (%2; %3) nicht gegen den Uhrzeigersinn um das Drehzentrum (sein Polarwinkel wächst dort nicht)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the point must be finite (got (%1, %2))</source>
        <translation>der Punkt muss endlich sein (ist (%1; %2))</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the point is the rotation centre, which no arc of the contour can reach</source>
        <translation>der Punkt ist das Drehzentrum, das kein Bogen der Kontur erreichen kann</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the point is the end point (%1, %2) of %3: an arc needs a second point</source>
        <translation>der Punkt ist der Endpunkt (%1; %2) von %3: ein Bogen braucht einen zweiten Punkt</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the point is on the tangent: use a line (an arc through it would need a radius or centre beyond 1e6 mm, the largest length a project holds)</source>
        <translation>der Punkt liegt auf der Tangente: eine Gerade verwenden (ein Bogen durch ihn bräuchte einen Radius oder Mittelpunkt jenseits von 10⁶ mm, der größten Länge, die ein Projekt fasst)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the arc's radius would be %1 mm, below %2 mm, the smallest a project holds</source>
        <translation>der Radius des Bogens wäre %1 mm, unter %2 mm, dem kleinsten, den ein Projekt fasst</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the end point of %1 is not on the outer branch of the circle (centre (%2, %3), radius %4 mm)</source>
        <translation>der Endpunkt von %1 liegt nicht auf dem Zweig „außen“ des Kreises (Mittelpunkt (%2; %3), Radius %4 mm)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the end point of %1 is not on the inner branch of the circle (centre (%2, %3), radius %4 mm)</source>
        <translation>der Endpunkt von %1 liegt nicht auf dem Zweig „innen“ des Kreises (Mittelpunkt (%2; %3), Radius %4 mm)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the point lies on the near side of the circle (centre (%1, %2), radius %3 mm) as seen from the rotation centre, but the arc leaves %4 on its far side (outer branch): the follower ray would not meet the arc at the point</source>
        <translation>der Punkt liegt, vom Drehzentrum aus gesehen, auf der nahen Seite des Kreises (Mittelpunkt (%1; %2), Radius %3 mm), aber der Bogen verlässt %4 auf dessen ferner Seite (Zweig „außen“): der Strahl des Stößels träfe den Bogen nicht im Punkt</translation>
    </message>
    <message>
        <location line="+6" />
        <source>the point lies on the far side of the circle (centre (%1, %2), radius %3 mm) as seen from the rotation centre, but the arc leaves %4 on its near side (inner branch): the follower ray would not meet the arc at the point</source>
        <translation>der Punkt liegt, vom Drehzentrum aus gesehen, auf der fernen Seite des Kreises (Mittelpunkt (%1; %2), Radius %3 mm), aber der Bogen verlässt %4 auf dessen naher Seite (Zweig „innen“): der Strahl des Stößels träfe den Bogen nicht im Punkt</translation>
    </message>
    <message>
        <location line="+6" />
        <source>the point lies behind the end point of %1 as seen from the rotation centre: the arc along the circle (centre (%2, %3), radius %4 mm) would pass to its near side and run back before reaching it</source>
        <translation>der Punkt liegt, vom Drehzentrum aus gesehen, hinter dem Endpunkt von %1: der Bogen entlang des Kreises (Mittelpunkt (%2; %3), Radius %4 mm) ginge auf dessen nahe Seite über und liefe zurück, bevor er ihn erreicht</translation>
    </message>
    <message>
        <location line="+5" />
        <source>the point lies behind the end point of %1 as seen from the rotation centre: the arc along the circle (centre (%2, %3), radius %4 mm) would pass to its far side and run back before reaching it</source>
        <translation>der Punkt liegt, vom Drehzentrum aus gesehen, hinter dem Endpunkt von %1: der Bogen entlang des Kreises (Mittelpunkt (%2; %3), Radius %4 mm) ginge auf dessen ferne Seite über und liefe zurück, bevor er ihn erreicht</translation>
    </message>
    <message>
        <location line="+5" />
        <source>the point lies on the follower ray at the end %1° of %2: the arc's window would be empty</source>
        <translation>der Punkt liegt auf dem Strahl des Stößels am Ende %1° von %2: das Fenster des Bogens wäre leer</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the arc would end at %1° (the polar angle of the point), not before the end %2° of %3, whose window would be empty or reversed</source>
        <translation>der Bogen endete bei %1° (dem Polarwinkel des Punkts), nicht vor dem Ende %2° von %3, dessen Fenster leer oder umgekehrt wäre</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the point is the end point of %1, which would have no length left</source>
        <translation>der Punkt ist der Endpunkt von %1, dem keine Länge bliebe</translation>
    </message>
    <message>
        <location line="+3" />
        <source>with its start point moved to the point, %1 would no longer run counter-clockwise from %2° to its end %3°</source>
        <translation>mit seinem Anfangspunkt im Punkt liefe %1 nicht mehr gegen den Uhrzeigersinn von %2° bis zu seinem Ende %3°</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the tolerance must be between %1 and %2 mm, not %3</source>
        <translation>die Toleranz muss zwischen %1 und %2 mm liegen, nicht %3</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the tool radius must be above 0 and at most %1 mm, not %2</source>
        <translation>der Werkzeugradius muss über 0 und höchstens %1 mm sein, nicht %2</translation>
    </message>
    <message>
        <location line="+2" />
        <source>with cutter compensation the tool would have to reach past the next programmed arc at a concave corner of this segment, which a controller offsetting one move at a time turns into a cut through the part; export the tool-centre path (without --compensation) or use a coarser --tolerance</source>
        <translation>mit Werkzeugradiuskorrektur müsste das Werkzeug an einer konkaven Ecke dieses Segments über den nächsten programmierten Bogen hinausreichen, was eine Steuerung, die Satz für Satz versetzt, in einen Schnitt durch das Werkstück verwandelt; die Werkzeugmittelpunktsbahn exportieren (ohne --compensation) oder eine gröbere --tolerance verwenden</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1 must be above 0 and at most %2 mm, not %3</source>
        <translation>%1 muss über 0 und höchstens %2 mm sein, nicht %3</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the feed must be above 0 and at most %1 mm/min, not %2</source>
        <translation>der Vorschub muss über 0 und höchstens %1 mm/min sein, nicht %2</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the tool number must be from 1 to 99999, not %1</source>
        <translation>die Werkzeugnummer muss zwischen 1 und 99999 liegen, nicht %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>a step-down of %1 mm makes %2 passes for a depth of %3 mm; at most %4 are made</source>
        <translation>eine Zustellung von %1 mm ergibt %2 Durchgänge für eine Tiefe von %3 mm; höchstens %4 werden gefahren</translation>
    </message>
    <message>
        <location line="+4" />
        <source>a cam table has from %1 to %2 points, not %3</source>
        <translation>eine Kurvenscheibentabelle hat %1 bis %2 Punkte, nicht %3</translation>
    </message>
    <message>
        <location line="+2" />
        <source>is not a finite number (%1): the result is beyond what a double can hold</source>
        <translation>ist keine endliche Zahl (%1): das Ergebnis übersteigt, was ein double fassen kann</translation>
    </message>
    <message>
        <location line="+2" />
        <source>must be at least 1 (got 0)</source>
        <translation>muss mindestens 1 sein (ist 0)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>is not a finite number, which a file cannot hold</source>
        <translation>ist keine endliche Zahl; eine Datei kann sie nicht speichern</translation>
    </message>
    <message>
        <location line="+1" />
        <source>cannot open: %1</source>
        <translation>kann nicht geöffnet werden: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>cannot examine: %1</source>
        <translation>kann nicht untersucht werden: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>cannot read: %1</source>
        <translation>kann nicht gelesen werden: %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>is %1, not a regular file: not read</source>
        <translation>ist %1, keine reguläre Datei: nicht gelesen</translation>
    </message>
    <message>
        <location line="+2" />
        <source>is %1 MiB (%2 bytes): files larger than %3 MiB are not read</source>
        <translation>ist %1 MiB groß (%2 Bytes): Dateien über %3 MiB werden nicht gelesen</translation>
    </message>
    <message>
        <location line="+3" />
        <source>grew past %1 MiB while it was read: larger files are not read</source>
        <translation>wuchs beim Lesen über %1 MiB: größere Dateien werden nicht gelesen</translation>
    </message>
    <message>
        <location line="+2" />
        <source>no file name given</source>
        <translation>kein Dateiname angegeben</translation>
    </message>
    <message>
        <location line="+1" />
        <source>cannot examine %1: %2</source>
        <translation>%1 kann nicht untersucht werden: %2</translation>
    </message>
    <message>
        <location line="+2" />
        <source>cannot follow its symbolic links: %1</source>
        <translation>ihren symbolischen Links kann nicht gefolgt werden: %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>cannot read the symbolic link %1: %2</source>
        <translation>der symbolische Link %1 kann nicht gelesen werden: %2</translation>
    </message>
    <message>
        <location line="+2" />
        <source>is a link to an open file descriptor, not a file: not replaced</source>
        <translation>ist ein Link auf einen offenen Dateideskriptor, keine Datei: nicht ersetzt</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1 is a link to an open file descriptor, not a file: not replaced</source>
        <translation>%1 ist ein Link auf einen offenen Dateideskriptor, keine Datei: nicht ersetzt</translation>
    </message>
    <message>
        <location line="+3" />
        <source>is %1, not a regular file: not replaced</source>
        <translation>ist %1, keine reguläre Datei: nicht ersetzt</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 is %2, not a regular file: not replaced</source>
        <translation>%1 ist %2, keine reguläre Datei: nicht ersetzt</translation>
    </message>
    <message>
        <location line="+1" />
        <source>cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>names a folder, not a file</source>
        <translation>bezeichnet einen Ordner, keine Datei</translation>
    </message>
    <message>
        <location line="+2" />
        <source>cannot create a temporary file in %1: %2</source>
        <translation>in %1 kann keine temporäre Datei angelegt werden: %2</translation>
    </message>
    <message>
        <location line="+2" />
        <source>cannot give the new file the owner of %1: %2</source>
        <translation>die neue Datei kann nicht den Eigentümer von %1 erhalten: %2</translation>
    </message>
    <message>
        <location line="+2" />
        <source>cannot give the new file the permissions of %1: %2</source>
        <translation>die neue Datei kann nicht die Zugriffsrechte von %1 erhalten: %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>cannot flush %1 to disk: %2</source>
        <translation>%1 kann nicht auf den Datenträger geschrieben werden: %2</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 became %2 while it was written: not replaced</source>
        <translation>%1 ist während des Schreibens %2 geworden: nicht ersetzt</translation>
    </message>
    <message>
        <location line="+1" />
        <source>cannot replace %1: %2</source>
        <translation>%1 kann nicht ersetzt werden: %2</translation>
    </message>
    <message>
        <location line="+2" />
        <source>replaced, but cannot close %1: %2</source>
        <translation>ersetzt, aber %1 kann nicht geschlossen werden: %2</translation>
    </message>
    <message>
        <location line="+2" />
        <source>replaced, but cannot flush the folder %1 to disk: %2</source>
        <translation>ersetzt, aber der Ordner %1 kann nicht auf den Datenträger geschrieben werden: %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>no such segment</source>
        <translation>dieses Segment gibt es nicht</translation>
    </message>
    <message>
        <location line="+1" />
        <source>is not an arc</source>
        <translation>ist kein Bogen</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the admissible radial error must be &gt; 0 mm</source>
        <translation>der zulässige radiale Fehler muss &gt; 0 mm sein</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the ray at the window's start does not meet the arc</source>
        <translation>der Strahl des Stößels am Anfang des Fensters trifft den Bogen nicht</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the ray at the window's end does not meet the arc</source>
        <translation>der Strahl des Stößels am Ende des Fensters trifft den Bogen nicht</translation>
    </message>
    <message>
        <location line="+2" />
        <source>a spline needs at least two points</source>
        <translation>ein Spline braucht mindestens zwei Stützpunkte</translation>
    </message>
    <message>
        <location line="+2" />
        <source>a closed spline needs at least three points</source>
        <translation>ein geschlossener Spline braucht mindestens drei Stützpunkte</translation>
    </message>
    <message>
        <location line="+2" />
        <source>must be a finite factor &gt; 0 (got %1)</source>
        <translation>muss ein endlicher Faktor &gt; 0 sein (ist %1)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the neighbouring segments miss each other by %1 mm, more than the typing tolerance of 1e-05 mm, so there is no boundary to fit</source>
        <translation>die benachbarten Segmente verfehlen sich um %1 mm, mehr als die Tipptoleranz von 10⁻⁵ mm, daher gibt es keine Grenze anzupassen</translation>
    </message>
    <message>
        <location line="+4" />
        <source>making the neighbouring segments meet would move %1 by %2 mm in all, more than the typing tolerance of 1e-05 mm</source>
        <translation>damit sich die benachbarten Segmente treffen, müsste sich %1 insgesamt um %2 mm ändern, mehr als die Tipptoleranz von 10⁻⁵ mm</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the neighbouring segments still miss each other by %1 mm after %2 rounds of moves; type the centres more exactly</source>
        <translation>die benachbarten Segmente verfehlen sich nach %2 Runden von Verschiebungen noch um %1 mm; bitte die Mittelpunkte genauer eingeben</translation>
    </message>
    <message>
        <location line="+4" />
        <source>moved by %1 mm, from (%2, %3) to (%4, %5), so that the circle touches %6 (they missed each other by less than the typing tolerance of 1e-05 mm)</source>
        <translation>um %1 mm verschoben, von (%2, %3) nach (%4, %5), damit der Kreis %6 berührt (sie verfehlten sich um weniger als die Tipptoleranz von 10⁻⁵ mm)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>changed by %1 mm, centre (%2, %3) and radius %4 mm to centre (%5, %6) and radius %7 mm, so that the circle touches both %8 and %9 (they missed each other by less than the typing tolerance of 1e-05 mm)</source>
        <translation>um %1 mm geändert, Mittelpunkt (%2, %3) und Radius %4 mm zu Mittelpunkt (%5, %6) und Radius %7 mm, damit der Kreis sowohl %8 als auch %9 berührt (sie verfehlten sich um weniger als die Tipptoleranz von 10⁻⁵ mm)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>made the same circle as %1: moved by %2 mm, to centre (%3, %4) and radius %5 mm (the two pieces differed by less than the typing tolerance of 1e-05 mm)</source>
        <translation>zum selben Kreis wie %1 gemacht: um %2 mm verschoben, zu Mittelpunkt (%3, %4) und Radius %5 mm (die beiden Stücke unterschieden sich um weniger als die Tipptoleranz von 10⁻⁵ mm)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>moved by %1 mm across its direction so that it meets %2 (they missed each other by less than the typing tolerance of 1e-05 mm)</source>
        <translation>um %1 mm quer zu ihrer Richtung verschoben, damit sie %2 trifft (sie verfehlten sich um weniger als die Tipptoleranz von 10⁻⁵ mm)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>is empty: the design's contour was never synthesised (camwright-cli synthesize makes it)</source>
        <translation>ist leer: die Kontur des Entwurfs wurde noch nie synthetisiert (camwright-cli synthesize erzeugt sie)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the project has no design to synthesise a contour from</source>
        <translation>das Projekt hat keinen Bewegungsentwurf, aus dem sich eine Kontur synthetisieren ließe</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the synthesised arc table is not a valid contour: %1</source>
        <translation>die synthetisierte Bogentabelle ist keine gültige Kontur: %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the synthesised arc table is not a valid contour: %1, made for the cam angles %2° to %3° (%4)</source>
        <translation>die synthetisierte Bogentabelle ist keine gültige Kontur: %1, erzeugt für die Nockenwinkel %2° bis %3° (%4)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>cannot be met near %1°: no arcs come within it even on pieces of 2^-%2 of the profile's sampling step (the profile has a corner or a cusp there)</source>
        <translation>ist bei %1° nicht einzuhalten: selbst auf Stücken von 2^-%2 der Abtastschrittweite des Profils kommen keine Bögen so nahe (das Profil hat dort eine Ecke oder Spitze)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 mm is below what double precision can certify for this cam: at least %2 mm, for a profile reaching %3 mm from the centre</source>
        <translation>%1 mm liegt unter dem, was doppelte Genauigkeit für diesen Nocken bestätigen kann: mindestens %2 mm, bei einem Profil, das %3 mm vom Mittelpunkt reicht</translation>
    </message>
    <message>
        <location line="+4" />
        <source>cannot be met: the closest arc table found lies %2 mm from the exact profile (at %3° of cam angle), more than the %1 mm asked for</source>
        <translation>ist nicht einzuhalten: die beste gefundene Bogentabelle liegt %2 mm vom exakten Profil entfernt (bei %3° Nockenwinkel), mehr als die verlangten %1 mm</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the follower's line (offset %1 mm) passes outside the base circle of radius %2 mm: make the base radius larger than the offset</source>
        <translation>die Stößelgerade (Versatz %1 mm) verläuft außerhalb des Grundkreises mit Radius %2 mm: den Grundkreisradius größer als den Versatz wählen</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the follower's line (offset %1 mm) passes outside the base circle of radius %2 mm (base radius + roller radius): make the base radius larger than the offset</source>
        <translation>die Stößelgerade (Versatz %1 mm) verläuft außerhalb des Grundkreises mit Radius %2 mm (Grundkreisradius + Rollenradius): den Grundkreisradius größer als den Versatz wählen</translation>
    </message>
    <message>
        <location line="+5" />
        <source>an arm of %1 mm from a pivot %2 mm from the centre cannot touch the base circle of radius %3 mm</source>
        <translation>ein Schwinghebel von %1 mm Länge, dessen Drehpunkt %2 mm vom Scheibenmittelpunkt entfernt ist, kann den Grundkreis mit Radius %3 mm nicht berühren</translation>
    </message>
    <message>
        <location line="+4" />
        <source>an arm of %1 mm from a pivot %2 mm from the centre cannot touch the base circle of radius %3 mm (base radius + roller radius)</source>
        <translation>ein Schwinghebel von %1 mm Länge, dessen Drehpunkt %2 mm vom Scheibenmittelpunkt entfernt ist, kann den Grundkreis mit Radius %3 mm (Grundkreisradius + Rollenradius) nicht berühren</translation>
    </message>
    <message>
        <location line="+4" />
        <source>undercut: the pitch curve bends tighter than the roller radius %1 mm from %2° to %3°</source>
        <translation>Unterschnitt: von %2° bis %3° ist die Rollenmittelpunktsbahn enger gekrümmt als der Rollenradius %1 mm</translation>
    </message>
    <message>
        <location line="+4" />
        <source>undercut: the face's envelope folds back (h + h'' &lt; 0) from %1° to %2°</source>
        <translation>Unterschnitt: von %1° bis %2° schlägt die Hüllkurve des Flachstößels zurück (h + h'' &lt; 0)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the pressure angle exceeds %1° from %2° to %3°</source>
        <translation>von %2° bis %3° überschreitet der Druckwinkel %1°</translation>
    </message>
    <message>
        <location line="+2" />
        <source>radius %1 mm gives a contour that does not validate (%2)</source>
        <translation>Radius %1 mm ergibt eine ungültige Kontur (%2)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>no base radius up to 1000000 mm passes every check: %1 fails at %2°</source>
        <translation>kein Grundkreisradius bis 1000000 mm besteht alle Prüfungen: %1 scheitert bei %2°</translation>
    </message>
    <message>
        <location line="+3" />
        <source>is for a swinging arm; this project's follower translates</source>
        <translation>gilt für einen Schwinghebel; der Stößel dieses Projekts bewegt sich geradlinig</translation>
    </message>
    <message>
        <location line="+2" />
        <source>is for a translating follower; this project's follower swings on an arm</source>
        <translation>gilt für einen geradlinigen Stößel; der Stößel dieses Projekts schwingt an einem Hebel</translation>
    </message>
    <message>
        <location line="+4" />
        <source>must be at least 0 and below 0.5 (got %1)</source>
        <translation>muss mindestens 0 und kleiner als 0,5 sein (ist %1)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <location filename="../../src/core/construction/tangents.cpp" line="+78" />
        <source>an arc</source>
        <translation>ein Bogen</translation>
    </message>
    <message>
        <location line="+2" />
        <source>a line</source>
        <translation>eine Gerade</translation>
    </message>
    <message>
        <location line="+2" />
        <source>a Bézier spline</source>
        <translation>ein Bézier-Spline</translation>
    </message>
    <message>
        <location line="+2" />
        <source>a Hermite spline</source>
        <translation>ein Hermite-Spline</translation>
    </message>
    <message>
        <location line="+2" />
        <source>a segment</source>
        <translation>ein Segment</translation>
    </message>
    <message>
        <location line="+24" />
        <source>the outer tangent</source>
        <translation>die äußere Tangente</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the inner tangent</source>
        <translation>die innere Tangente</translation>
    </message>
    <message>
        <location line="+190" />
        <source>a tangent line</source>
        <translation>eine Tangente</translation>
    </message>
    <message>
        <location filename="../../src/core/export/gcode.cpp" line="+473" />
        <source>the depth</source>
        <translation>die Tiefe</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the safe height</source>
        <translation>die sichere Höhe</translation>
    </message>
    <message>
        <location line="+14" />
        <source>the step-down</source>
        <translation>die Zustellung</translation>
    </message>
    <message>
        <location filename="../../src/core/fillet/fillet.cpp" line="+195" />
        <source>a fillet</source>
        <translation>eine Verrundung</translation>
    </message>
    <message>
        <location filename="../../src/core/follower/follower_arm.cpp" line="+310" />
        <source>the roller</source>
        <translation>die Rolle</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the tip</source>
        <translation>die Spitze</translation>
    </message>
    <message>
        <location filename="../../src/core/io/atomic_file.cpp" line="+138" />
        <source>a folder</source>
        <translation>ein Ordner</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a FIFO</source>
        <translation>eine FIFO</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a character device</source>
        <translation>ein zeichenorientiertes Gerät</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a block device</source>
        <translation>ein blockorientiertes Gerät</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a socket</source>
        <translation>ein Socket</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a special file</source>
        <translation>eine Spezialdatei</translation>
    </message>
    <message>
        <location filename="../../src/core/io/project_reader.cpp" line="+22" />
        <location line="+94" />
        <source>a string</source>
        <translation>ein Text</translation>
    </message>
    <message>
        <location line="-93" />
        <source>a boolean</source>
        <translation>ein Wahrheitswert</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+63" />
        <source>a number</source>
        <translation>eine Zahl</translation>
    </message>
    <message>
        <location line="-62" />
        <source>an array</source>
        <translation>ein Array</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+141" />
        <location line="+387" />
        <source>an object</source>
        <translation>ein Objekt</translation>
    </message>
    <message>
        <location line="-450" />
        <source>true or false</source>
        <translation>true oder false</translation>
    </message>
    <message>
        <location line="+28" />
        <source>an array [x, y] of two numbers</source>
        <translation>ein Array [x, y] aus zwei Zahlen</translation>
    </message>
    <message>
        <location line="+20" />
        <source>an array of numbers</source>
        <translation>ein Array aus Zahlen</translation>
    </message>
    <message>
        <location line="+327" />
        <location line="+120" />
        <source>an array of segments</source>
        <translation>ein Array aus Segmenten</translation>
    </message>
    <message>
        <location line="-79" />
        <source>an array of points [x, y] or [x, y, dy/dx]</source>
        <translation>eine Liste von Punkten [x, y] oder [x, y, dy/dx]</translation>
    </message>
    <message>
        <location line="+43" />
        <source>a whole number</source>
        <translation>eine ganze Zahl</translation>
    </message>
    <message>
        <location filename="../../src/core/design/sizing.cpp" line="+179" />
        <source>the pressure angle on rise</source>
        <translation>der Druckwinkel im Hub</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the pressure angle on return</source>
        <translation>der Druckwinkel im Rückhub</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the profile's convex radius</source>
        <translation>der konvexe Radius des Profils</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the follower's reach</source>
        <translation>die Reichweite des Stößels</translation>
    </message>
    <message>
        <location filename="../../src/core/design/boundary_classes.cpp" line="+34" />
        <source>rest</source>
        <translation>Rast</translation>
    </message>
    <message>
        <location line="+2" />
        <source>constant velocity</source>
        <translation>konstante Geschwindigkeit</translation>
    </message>
    <message>
        <location line="+2" />
        <source>reversal</source>
        <translation>Umkehr</translation>
    </message>
    <message>
        <location line="+2" />
        <source>movement</source>
        <translation>Bewegung</translation>
    </message>
    <message>
        <location filename="../../src/core/design/motion_design.cpp" line="+189" />
        <source>start</source>
        <translation>Anfang</translation>
    </message>
    <message>
        <location line="+1" />
        <source>end</source>
        <translation>Ende</translation>
    </message>
</context>
<context>
    <name>DiagnosticText</name>
    <message>
        <location filename="../../src/app/messages/diagnostic_text.cpp" line="+70" />
        <source>control point P%1</source>
        <translation>Kontrollpunkt P%1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>control points</source>
        <translation>Kontrollpunkte</translation>
    </message>
    <message>
        <location line="+3" />
        <source>start point</source>
        <translation>Anfangspunkt</translation>
    </message>
    <message>
        <location line="+3" />
        <source>start tangent</source>
        <translation>Anfangstangente</translation>
    </message>
    <message>
        <location line="+3" />
        <source>end point</source>
        <translation>Endpunkt</translation>
    </message>
    <message>
        <location line="+3" />
        <source>end tangent</source>
        <translation>Endtangente</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1, x</source>
        <translation>%1, x</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1, y</source>
        <translation>%1, y</translation>
    </message>
    <message>
        <location line="+178" />
        <source>law</source>
        <translation>Gesetz</translation>
    </message>
    <message>
        <location line="+2" />
        <source>end angle</source>
        <translation>Endwinkel</translation>
    </message>
    <message>
        <location line="+2" />
        <source>lift</source>
        <translation>Hub</translation>
    </message>
    <message>
        <location line="+25" />
        <source>Motion design, segment %1</source>
        <translation>Bewegungsentwurf, Segment %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Motion design, segment %1, %2</source>
        <translation>Bewegungsentwurf, Segment %1, %2</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Motion design, joint between segments %1 and %2</source>
        <translation>Bewegungsentwurf, Übergang zwischen Segment %1 und %2</translation>
    </message>
    <message>
        <location line="-110" />
        <source>Machining, acceleration of axis %1</source>
        <translation>Zerspanung, Beschleunigung der Achse %1</translation>
    </message>
    <message>
        <location line="-45" />
        <source>segment %1</source>
        <translation>Segment %1</translation>
    </message>
    <message>
        <location line="+49" />
        <source>Machining, speed limit of axis %1</source>
        <translation>Zerspanung, Geschwindigkeitsgrenze der Achse %1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Follower, pivot x</source>
        <translation>Stößel, Drehpunkt des Hebels x</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Follower, pivot y</source>
        <translation>Stößel, Drehpunkt des Hebels y</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Point %1</source>
        <translation>Punkt %1</translation>
    </message>
    <message>
        <location line="+6" />
        <location line="+80" />
        <source>Contour</source>
        <translation>Kontur</translation>
    </message>
    <message>
        <location line="-79" />
        <source>Points</source>
        <translation>Punkte</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Bulge factor</source>
        <translation>Wölbungsfaktor</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Admissible radial error</source>
        <translation>Zulässiger radialer Fehler</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Motion, ω [rad/s]</source>
        <translation>Bewegung, ω [rad/s]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Motion, speed [rpm]</source>
        <translation>Bewegung, Drehzahl [1/min]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Motion, period [s]</source>
        <translation>Bewegung, Periode [s]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Follower, offset</source>
        <translation>Stößel, Versatz</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Follower, roller radius</source>
        <translation>Stößel, Rollenradius</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Follower, largest pressure angle</source>
        <translation>Stößel, größter Druckwinkel</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Follower, type</source>
        <translation>Stößel, Typ</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Follower, pivot</source>
        <translation>Stößel, Drehpunkt des Hebels</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Follower, arm length</source>
        <translation>Stößel, Hebellänge</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Follower, closure</source>
        <translation>Stößel, Schlussart</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Follower, groove clearance</source>
        <translation>Stößel, Spiel in der Nut</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Follower, groove's inner land radius</source>
        <translation>Stößel, innerer Stegradius der Nut</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Follower, groove's outer land radius</source>
        <translation>Stößel, äußerer Stegradius der Nut</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Follower, second roller's distance</source>
        <translation>Stößel, Abstand der zweiten Rolle</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Follower, second roller's radius</source>
        <translation>Stößel, Radius der zweiten Rolle</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Follower, second arm's angle</source>
        <translation>Stößel, Winkel des zweiten Arms</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Follower, second arm's length</source>
        <translation>Stößel, Länge des zweiten Arms</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Samples per turn</source>
        <translation>Abtastpunkte pro Umdrehung</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Machining, axis accelerations</source>
        <translation>Zerspanung, Achsbeschleunigungen</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Machining, axis speed limits</source>
        <translation>Zerspanung, Achsgeschwindigkeitsgrenzen</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Machining, feed ceiling</source>
        <translation>Zerspanung, höchster Vorschub</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Machining, tool radius</source>
        <translation>Zerspanung, Werkzeugradius</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Machining, step</source>
        <translation>Zerspanung, Schrittweite</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Motion design</source>
        <translation>Bewegungsentwurf</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Motion design, base radius</source>
        <translation>Bewegungsentwurf, Grundkreisradius</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Motion design, tolerance</source>
        <translation>Bewegungsentwurf, Toleranz</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Motion design, segments</source>
        <translation>Bewegungsentwurf, Segmente</translation>
    </message>
    <message>
        <location line="-83" />
        <source>is empty: the design's contour was never synthesised (Synthesize Contour, F6, makes it)</source>
        <translation>ist leer: die Kontur des Entwurfs wurde noch nie synthetisiert (Kontur synthetisieren, F6, erzeugt sie)</translation>
    </message>
    <message>
        <location line="+119" />
        <source>Joint between segments %1 and %2</source>
        <translation>Übergang zwischen Segment %1 und %2</translation>
    </message>
    <message>
        <location line="-5" />
        <source>Segment %1</source>
        <translation>Segment %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Segment %1, %2</source>
        <translation>Segment %1, %2</translation>
    </message>
    <message>
        <location line="+25" />
        <source>line %1</source>
        <translation>Zeile %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>line %1, column %2</source>
        <translation>Zeile %1, Spalte %2</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Dynamics, %1</source>
        <translation>Dynamik, %1</translation>
    </message>
    <message>
        <location line="+4" />
        <source>sample %1, %2</source>
        <translation>Abtastpunkt %1, %2</translation>
    </message>
    <message>
        <location line="+33" />
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>DynamicsKey</name>
    <message>
        <location filename="../../src/app/messages/field_titles.cpp" line="+46" />
        <source>Moving mass [kg]</source>
        <translation>Bewegte Masse [kg]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Spring rate [N/mm]</source>
        <translation>Federrate [N/mm]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Spring preload [N]</source>
        <translation>Federvorspannung [N]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>External force [N]</source>
        <translation>Äußere Kraft [N]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Damping [N·s/m]</source>
        <translation>Dämpfung [N·s/m]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Arm inertia [kg·m²]</source>
        <translation>Trägheitsmoment des Hebels [kg·m²]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Spring rate [N·m/rad]</source>
        <translation>Federrate [N·m/rad]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Spring preload [N·m]</source>
        <translation>Federvorspannung [N·m]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>External moment [N·m]</source>
        <translation>Äußeres Moment [N·m]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Damping [N·m·s/rad]</source>
        <translation>Dämpfung [N·m·s/rad]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Contact width [mm]</source>
        <translation>Kontaktbreite [mm]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Cam material, E [MPa]</source>
        <translation>Werkstoff der Kurvenscheibe, E [MPa]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Cam material, Poisson's ratio</source>
        <translation>Werkstoff der Kurvenscheibe, Querkontraktionszahl</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Follower material, E [MPa]</source>
        <translation>Werkstoff des Stößels, E [MPa]</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Follower material, Poisson's ratio</source>
        <translation>Werkstoff des Stößels, Querkontraktionszahl</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Allowable contact stress [MPa]</source>
        <translation>Zulässige Pressung [MPa]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Spring safety factor</source>
        <translation>Sicherheitsfaktor der Feder</translation>
    </message>
</context>
<context>
    <name>ExportFormat</name>
    <message>
        <location filename="../../src/core/export/export_formats.cpp" line="+27" />
        <source>CSV</source>
        <translation>CSV</translation>
    </message>
    <message>
        <location line="+1" />
        <source>CODESYS Structured Text (SMC_CAMXYVA)</source>
        <translation>CODESYS Strukturierter Text (SMC_CAMXYVA)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Beckhoff TwinCAT Structured Text (MC_MotionFunctionPoint)</source>
        <translation>Beckhoff TwinCAT Strukturierter Text (MC_MotionFunctionPoint)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Rockwell Logix Structured Text (CAM array)</source>
        <translation>Rockwell Logix Strukturierter Text (CAM-Array)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Kollmorgen KAS cam profile CSV</source>
        <translation>Kollmorgen KAS Kurvenprofil-CSV</translation>
    </message>
    <message>
        <location line="+10" />
        <source>PNG image</source>
        <translation>PNG-Bild</translation>
    </message>
    <message>
        <location line="+1" />
        <source>PDF document (vector)</source>
        <translation>PDF-Dokument (Vektor)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>SVG drawing (vector)</source>
        <translation>SVG-Zeichnung (Vektor)</translation>
    </message>
    <message>
        <location line="+7" />
        <source>CSV: the sampled turn</source>
        <translation>CSV: die abgetastete Umdrehung</translation>
    </message>
    <message>
        <location line="+7" />
        <source>DXF drawing (R2000, mm)</source>
        <translation>DXF-Zeichnung (R2000, mm)</translation>
    </message>
    <message>
        <location line="+7" />
        <source>SVG drawing, 1:1 in mm</source>
        <translation>SVG-Zeichnung, 1:1 in mm</translation>
    </message>
    <message>
        <location line="+7" />
        <source>G-code for milling the cam</source>
        <translation>G-Code zum Fräsen der Kurvenscheibe</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Servo cam table</source>
        <translation>Kurvenscheibentabelle für Servoantriebe</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Picture of a plot (PNG, PDF, SVG)</source>
        <translation>Bild eines Diagramms (PNG, PDF, SVG)</translation>
    </message>
</context>
<context>
    <name>ExportRequest</name>
    <message>
        <location filename="../../src/app/export/export_request.cpp" line="+40" />
        <source>the project has no design: its law is the source only of a design's table</source>
        <translation>das Projekt hat keinen Entwurf: sein Bewegungsgesetz ist nur bei einem Entwurf die Quelle der Tabelle</translation>
    </message>
    <message>
        <location line="+10" />
        <source>the project has no contour yet: Synthesize (F6) makes it from the design</source>
        <translation>das Projekt hat noch keine Kontur: Synthetisieren (F6) erzeugt sie aus dem Entwurf</translation>
    </message>
</context>
<context>
    <name>FollowerKind</name>
    <message>
        <location filename="../../src/core/project/follower_kind.cpp" line="+14" />
        <source>Knife edge</source>
        <translation>Spitze (Messerkante)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Roller</source>
        <translation>Rolle</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Flat face</source>
        <translation>Flachstößel</translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <location filename="../../ui/mainwindow.ui" line="+6" />
        <source>Camwright</source>
        <translation>Camwright</translation>
    </message>
    <message>
        <location line="+4" />
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Examples</source>
        <translation>B&amp;eispiele</translation>
    </message>
    <message>
        <location line="+4" />
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location line="+3" />
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location line="+3" />
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Main Toolbar</source>
        <translation>Hauptwerkzeugleiste</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Segments</source>
        <translation>Segmente</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Motion</source>
        <translation>Bewegung</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Joints</source>
        <translation>Übergänge</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Path Study</source>
        <translation>Bahnstudie</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Machining</source>
        <translation>Zerspanung</translation>
    </message>
    <message>
        <location line="+5" />
        <source>State at Cursor</source>
        <translation>Zustand am Cursor</translation>
    </message>
    <message>
        <location line="+4" />
        <source>&amp;Close</source>
        <translation>S&amp;chließen</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Close the project (asks about unsaved changes); a new one takes its place</source>
        <translation>Projekt schließen (fragt nach ungespeicherten Änderungen); ein neues tritt an seine Stelle</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Project &amp;Name…</source>
        <translation>Projektna&amp;me…</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Rename the project: its name is the title of exported pictures and SVG files, the G-code program's first comment and the cam table's name</source>
        <translation>Projekt umbenennen: Der Name ist Titel exportierter Bilder und SVG-Dateien, erster Kommentar des G-Code-Programms und Name der Kurvenscheibentabelle</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;New</source>
        <translation>&amp;Neu</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Start a new project</source>
        <translation>Ein neues Projekt beginnen</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Open…</source>
        <translation>Ö&amp;ffnen…</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Open a .cam.json project</source>
        <translation>Ein .cam.json-Projekt öffnen</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Save the project</source>
        <translation>Das Projekt speichern</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter…</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Save the project under a new name</source>
        <translation>Das Projekt unter neuem Namen speichern</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Quit Camwright</source>
        <translation>Camwright beenden</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Insert Segment</source>
        <translation>Segment &amp;einfügen</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Insert a segment after the selected one</source>
        <translation>Ein Segment nach dem ausgewählten einfügen</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Delete Segment</source>
        <translation>Segment &amp;löschen</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Delete the selected segment</source>
        <translation>Das ausgewählte Segment löschen</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Move &amp;Up</source>
        <translation>Nach &amp;oben</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Move the selected segment up</source>
        <translation>Das ausgewählte Segment nach oben verschieben</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Move Do&amp;wn</source>
        <translation>Nach &amp;unten</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Move the selected segment down</source>
        <translation>Das ausgewählte Segment nach unten verschieben</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Fit Windows</source>
        <translation>Fenster &amp;anpassen</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Set every window boundary to where its neighbours meet; segments that miss each other by less than 1e-5 mm are made to meet by the smallest change (one undo step, every change listed)</source>
        <translation>Jede Fenstergrenze dorthin setzen, wo sich die Nachbarn treffen; Segmente, die einander um weniger als 1e-5 mm verfehlen, werden mit der kleinsten Änderung zum Treffen gebracht (ein Rückgängig-Schritt, jede Änderung aufgelistet)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Time Axis</source>
        <translation>&amp;Zeitachse</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Plot over time instead of angle</source>
        <translation>Über der Zeit statt über dem Winkel auftragen</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Reset Zoom</source>
        <translation>Zoom &amp;zurücksetzen</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Fit the contour and the plots into view</source>
        <translation>Kontur und Diagramme einpassen</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;About Camwright</source>
        <translation>Ü&amp;ber Camwright</translation>
    </message>
    <message>
        <location line="+0" />
        <source>About Camwright</source>
        <translation>Über Camwright</translation>
    </message>
</context>
<context>
    <name>Material</name>
    <message>
        <location filename="../../src/core/project/dynamics.cpp" line="+53" />
        <source>Steel</source>
        <translation>Stahl</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Hardened bearing steel (100Cr6)</source>
        <translation>Gehärteter Wälzlagerstahl (100Cr6)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Grey cast iron (EN-GJL-250)</source>
        <translation>Gusseisen mit Lamellengraphit (EN-GJL-250)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Nodular cast iron (EN-GJS-400-15)</source>
        <translation>Gusseisen mit Kugelgraphit (EN-GJS-400-15)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Tin bronze (CuSn12)</source>
        <translation>Zinnbronze (CuSn12)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>POM (acetal)</source>
        <translation>POM (Polyacetal)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>PA 6 (dry)</source>
        <translation>PA 6 (trocken)</translation>
    </message>
</context>
<context>
    <name>MotionLaw</name>
    <message>
        <location filename="../../src/core/design/motion_law.cpp" line="+152" />
        <source>Dwell</source>
        <translation>Rast</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Rest: the follower keeps its lift.</source>
        <translation>Rast: der Stößel behält seinen Hub.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Harmonic</source>
        <translation>Harmonisch (Kosinus)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Reversal to reversal: v = 0 at both ends; beside a dwell its acceleration jumps.</source>
        <translation>Umkehr zu Umkehr: v = 0 an beiden Enden; neben einer Rast springt die Beschleunigung.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Cycloidal</source>
        <translation>Zykloide</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Rest to rest with finite jerk.</source>
        <translation>Rast zu Rast mit endlichem Ruck.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Modified trapezoid</source>
        <translation>Modifiziertes Beschleunigungstrapez</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Rest to rest, the lowest acceleration with finite jerk; λ moves its inflection point (asymmetric).</source>
        <translation>Rast zu Rast, die kleinste Beschleunigung bei endlichem Ruck; λ verschiebt den Wendepunkt (unsymmetrisch).</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Modified sine</source>
        <translation>Modifizierte Sinuslinie</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Rest to rest, low velocity and acceleration together; λ moves its inflection point.</source>
        <translation>Rast zu Rast, kleine Geschwindigkeit und Beschleunigung zugleich; λ verschiebt den Wendepunkt.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Poly 3-4-5</source>
        <translation>Polynom 3-4-5</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Rest to rest, a polynomial of degree 5.</source>
        <translation>Rast zu Rast, ein Polynom 5. Grades.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Poly 4-5-6-7</source>
        <translation>Polynom 4-5-6-7</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Rest to rest with zero jerk at both ends.</source>
        <translation>Rast zu Rast mit Ruck null an beiden Enden.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Poly 5 (boundary values)</source>
        <translation>Polynom 5 (Randwerte)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Any boundary: velocity and acceleration at both ends.</source>
        <translation>Beliebige Randwerte: Geschwindigkeit und Beschleunigung an beiden Enden.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Constant velocity</source>
        <translation>Konstante Geschwindigkeit</translation>
    </message>
    <message>
        <location line="+2" />
        <source>A straight line: constant velocity, no acceleration.</source>
        <translation>Eine Gerade: konstante Geschwindigkeit, keine Beschleunigung.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Inclined sine (Bestehorn)</source>
        <translation>Geneigte Sinuslinie (Bestehorn)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Constant velocity v0 to the same velocity, no acceleration at the ends (v0 = 0: the cycloid).</source>
        <translation>Konstante Geschwindigkeit v0 zur gleichen Geschwindigkeit, keine Beschleunigung an den Enden (v0 = 0: die Zykloide).</translation>
    </message>
    <message>
        <location line="+3" />
        <source>SCCA (sine-constant-cosine)</source>
        <translation>SCCA (Sinus-Konstant-Kosinus)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Rest to rest; b and d are the shares of the sine ramps and of the cosine, the rest constant acceleration (Norton).</source>
        <translation>Rast zu Rast; b und d sind die Anteile der Sinusrampen und des Kosinus, der Rest konstante Beschleunigung (Norton).</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Poly 7 (boundary values)</source>
        <translation>Polynom 7 (Randwerte)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Any boundary: velocity, acceleration and jerk at both ends.</source>
        <translation>Beliebige Randwerte: Geschwindigkeit, Beschleunigung und Ruck an beiden Enden.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Motion table</source>
        <translation>Bewegungstabelle</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Your points (0…1, as Inventor takes them) joined by a C2 quintic spline, at rest at both ends.</source>
        <translation>Ihre Punkte (0…1, wie Inventor sie nimmt), verbunden durch einen C2-Spline 5. Grades, in Rast an beiden Enden.</translation>
    </message>
</context>
<context>
    <name>PlotKind</name>
    <message>
        <location filename="../../src/app/export/plot_picture.cpp" line="+132" />
        <source>Contour</source>
        <translation>Kontur</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Velocity</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Acceleration</source>
        <translation>Beschleunigung</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Jerk</source>
        <translation>Ruck</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Feed along the path</source>
        <translation>Vorschub entlang der Bahn</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Axis accelerations</source>
        <translation>Achsbeschleunigungen</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Pressure angle</source>
        <translation>Druckwinkel</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Lift</source>
        <translation>Hub</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Lift, velocity, acceleration, jerk</source>
        <translation>Hub, Geschwindigkeit, Beschleunigung, Ruck</translation>
    </message>
</context>
<context>
    <name>SegmentColumn</name>
    <message>
        <location filename="../../src/app/messages/field_titles.cpp" line="-53" />
        <source>Type</source>
        <translation>Typ</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Centre x [mm]</source>
        <translation>Mittelpunkt x [mm]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Centre y [mm]</source>
        <translation>Mittelpunkt y [mm]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Radius [mm]</source>
        <translation>Radius [mm]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Branch</source>
        <translation>Zweig</translation>
    </message>
    <message>
        <location line="+1" />
        <source>From x [mm]</source>
        <translation>Von x [mm]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>From y [mm]</source>
        <translation>Von y [mm]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>To x [mm]</source>
        <translation>Bis x [mm]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>To y [mm]</source>
        <translation>Bis y [mm]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>φ start [°]</source>
        <translation>φ Anfang [°]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>φ end [°]</source>
        <translation>φ Ende [°]</translation>
    </message>
</context>
<context>
    <name>cam::Autosave</name>
    <message>
        <location filename="../../src/app/files/autosave.cpp" line="+184" />
        <source>The recovery copy %1 cannot be read:
%2</source>
        <translation>Die Wiederherstellungskopie %1 ist nicht lesbar:
%2</translation>
    </message>
    <message>
        <location line="+14" />
        <source>The unsaved changes were restored, but their new recovery copy could not be written (%1); the old copy %2 is kept.</source>
        <translation>Die ungespeicherten Änderungen wurden wiederhergestellt, aber ihre neue Wiederherstellungskopie konnte nicht geschrieben werden (%1); die alte Kopie %2 bleibt erhalten.</translation>
    </message>
</context>
<context>
    <name>cam::Commands</name>
    <message>
        <location filename="../../src/app/document/commands.cpp" line="+32" />
        <source>Insert segment</source>
        <translation>Segment einfügen</translation>
    </message>
    <message>
        <location line="+12" />
        <source>Delete segment</source>
        <translation>Segment löschen</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Move segment</source>
        <translation>Segment verschieben</translation>
    </message>
    <message>
        <location line="+19" />
        <source>Change speed</source>
        <translation>Drehgeschwindigkeit ändern</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Rename project</source>
        <translation>Projekt umbenennen</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Change samples per turn</source>
        <translation>Abtastpunkte je Umdrehung ändern</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Change follower</source>
        <translation>Stößel ändern</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Change dynamics</source>
        <translation>Dynamik ändern</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Change machining limits</source>
        <translation>Bearbeitungsgrenzen ändern</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Synthesize contour</source>
        <translation>Kontur synthetisieren</translation>
    </message>
</context>
<context>
    <name>cam::ComputeWorker</name>
    <message>
        <location filename="../../src/app/engine/compute_engine.cpp" line="+47" />
        <source>out of memory — fewer samples per turn would need less</source>
        <translation>zu wenig Arbeitsspeicher – weniger Abtastpunkte pro Umdrehung bräuchten weniger</translation>
    </message>
    <message>
        <location line="+5" />
        <source>the computation failed: %1</source>
        <translation>die Berechnung ist fehlgeschlagen: %1</translation>
    </message>
</context>
<context>
    <name>cam::ContourDialogs</name>
    <message>
        <location filename="../../src/app/dialogs/contour_dialogs.cpp" line="+46" />
        <source>New Contour Through Points</source>
        <translation>Neue Kontur durch Punkte</translation>
    </message>
    <message>
        <location line="+4" />
        <source>x, y per line, in mm, counter-clockwise around the rotation centre</source>
        <translation>x, y je Zeile, in mm, gegen den Uhrzeigersinn um das Drehzentrum</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Chord</source>
        <translation>Sehne</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Circumcircle</source>
        <translation>Umkreis</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Oval</source>
        <translation>Oval</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Points</source>
        <translation>Punkte</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Handle rule</source>
        <translation>Griffregel</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Bulge factor</source>
        <translation>Wölbungsfaktor</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Approximate Arc by Béziers</source>
        <translation>Bogen durch Béziers annähern</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Admissible radial error:</source>
        <translation>Zulässiger radialer Fehler:</translation>
    </message>
</context>
<context>
    <name>cam::ContourEditTool</name>
    <message>
        <location filename="../../src/app/views/contour_edit_tool.cpp" line="+218" />
        <location line="+8" />
        <source>Shape segment %1</source>
        <translation>Segment %1 formen</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Move centre of segment %1</source>
        <translation>Mittelpunkt von Segment %1 verschieben</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Change radius of segment %1</source>
        <translation>Radius von Segment %1 ändern</translation>
    </message>
</context>
<context>
    <name>cam::ContourEdits</name>
    <message>
        <location filename="../../src/app/document/contour_edits.cpp" line="+17" />
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <location line="+41" />
        <source>Insert segment</source>
        <translation>Segment einfügen</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Split window</source>
        <translation>Fenster teilen</translation>
    </message>
    <message>
        <location line="+12" />
        <source>Select the segment to delete first.</source>
        <translation>Wählen Sie zuerst das zu löschende Segment.</translation>
    </message>
    <message>
        <location line="+10" />
        <source>The segment cannot move further.</source>
        <translation>Das Segment kann nicht weiter verschoben werden.</translation>
    </message>
    <message>
        <location line="+11" />
        <source>The windows already fit.</source>
        <translation>Die Fenster passen bereits.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Fit windows</source>
        <translation>Fenster anpassen</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Windows fitted to the joints.</source>
        <translation>Fenster an die Stoßstellen angepasst.</translation>
    </message>
    <message numerus="yes">
        <location line="+1" />
        <source>Windows fitted; %n segment(s) changed to meet, by at most %1.</source>
        <translation>
            <numerusform>Fenster angepasst; %n Segment zum Treffen geändert, um höchstens %1.</numerusform>
            <numerusform>Fenster angepasst; %n Segmente zum Treffen geändert, um höchstens %1.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+6" />
        <source>The project still has %n problem(s): %1</source>
        <translation>
            <numerusform>Das Projekt hat noch %n Problem: %1</numerusform>
            <numerusform>Das Projekt hat noch %n Probleme: %1</numerusform>
        </translation>
    </message>
    <message>
        <location line="+11" />
        <source>Select the segment after the corner to round.</source>
        <translation>Das Segment nach der zu verrundenden Ecke auswählen.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Round corner</source>
        <translation>Ecke verrunden</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Corner rounded with a %1 switch arc</source>
        <translation>Ecke mit einem Schaltbogen von %1 verrundet</translation>
    </message>
    <message>
        <location line="+32" />
        <source>Tangent arc: centre %1, radius %2</source>
        <translation>Tangentenbogen: Mittelpunkt %1, Radius %2</translation>
    </message>
    <message numerus="yes">
        <location line="+15" />
        <source>%n Bézier piece(s): radial error %1, end/middle speed ratio %2</source>
        <translation>
            <numerusform>%n Bézierstück: Radialabweichung %1, Geschwindigkeitsverhältnis Rand/Mitte %2</numerusform>
            <numerusform>%n Bézierstücke: Radialabweichung %1, Geschwindigkeitsverhältnis Rand/Mitte %2</numerusform>
        </translation>
    </message>
    <message>
        <location line="-40" />
        <source>Select the arc the tangent line starts from first.</source>
        <translation>Zuerst den Bogen auswählen, an dem die Tangente beginnt.</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Tangent line to the next arc</source>
        <translation>Tangente zum nächsten Bogen</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Tangent line from %1 to %2</source>
        <translation>Tangente von %1 nach %2</translation>
    </message>
    <message>
        <location line="+8" />
        <source>Select the segment the arc continues first.</source>
        <translation>Zuerst das Segment auswählen, das der Bogen fortsetzt.</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Tangent arc through a point</source>
        <translation>Tangentenbogen durch einen Punkt</translation>
    </message>
    <message>
        <location line="+8" />
        <source>Select the arc to approximate first.</source>
        <translation>Zuerst den anzunähernden Bogen auswählen.</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Approximate arc by Béziers</source>
        <translation>Bogen durch Béziers annähern</translation>
    </message>
    <message>
        <location line="+18" />
        <source>New contour through points</source>
        <translation>Neue Kontur durch Punkte</translation>
    </message>
    <message numerus="yes">
        <location line="+2" />
        <source>New contour through %n point(s)</source>
        <translation>
            <numerusform>Neue Kontur durch %n Punkt</numerusform>
            <numerusform>Neue Kontur durch %n Punkte</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>cam::ContourView</name>
    <message>
        <location filename="../../src/app/views/contour_view.cpp" line="+23" />
        <source>x [mm]</source>
        <translation>x [mm]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>y [mm]</source>
        <translation>y [mm]</translation>
    </message>
    <message>
        <location line="+11" />
        <source>Wheel: zoom · drag: pan · drag a square/diamond handle: move the centre or change the radius of the selected arc. Dragged points snap to centres, joints and the grid; Shift keeps one axis, Alt does not snap.</source>
        <translation>Mausrad: zoomen · Ziehen: verschieben · quadratischen/rautenförmigen Griff ziehen: Mittelpunkt verschieben oder Radius des gewählten Bogens ändern. Gezogene Punkte rasten an Mittelpunkten, Übergängen und am Raster ein; Umschalt hält eine Achse fest, Alt rastet nicht ein.</translation>
    </message>
    <message>
        <location line="+36" />
        <location line="+94" />
        <source>outer flank</source>
        <translation>Außenflanke</translation>
    </message>
    <message>
        <location line="-94" />
        <source>pitch curve</source>
        <translation>Rollenmittelpunktsbahn</translation>
    </message>
    <message>
        <location line="+9" />
        <source>centres</source>
        <translation>Mittelpunkte</translation>
    </message>
    <message>
        <location line="+5" />
        <source>joints</source>
        <translation>Übergänge</translation>
    </message>
    <message>
        <location line="+80" />
        <source>second plate</source>
        <translation>zweite Scheibe</translation>
    </message>
</context>
<context>
    <name>cam::ControlPointsPanel</name>
    <message>
        <location filename="../../src/app/views/control_points_panel.cpp" line="+41" />
        <source>x [mm]</source>
        <translation>x [mm]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>y [mm]</source>
        <translation>y [mm]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Handle length [mm]</source>
        <translation>Grifflänge [mm]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Handle angle [°]</source>
        <translation>Griffwinkel [°]</translation>
    </message>
    <message>
        <location line="+22" />
        <source>Length of the handle, mm (the angle stays)</source>
        <translation>Länge des Griffs, mm (der Winkel bleibt)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Direction of the handle, degrees counter-clockwise from +x (the length stays)</source>
        <translation>Richtung des Griffs, Grad gegen den Uhrzeigersinn ab +x (die Länge bleibt)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Start handle P0→P1</source>
        <translation>Anfangsgriff P0→P1</translation>
    </message>
    <message>
        <location line="+0" />
        <source>End handle P3→P2</source>
        <translation>Endgriff P3→P2</translation>
    </message>
    <message>
        <location line="+38" />
        <source>Edit %1 of segment %2</source>
        <translation>%1 von Segment %2 ändern</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Segment %1 is not a spline: its values are in the Segments table. Select a Bézier or Hermite row to edit its control points.</source>
        <translation>Segment %1 ist kein Spline: seine Werte stehen in der Segmenttabelle. Eine Bézier- oder Hermite-Zeile auswählen, um ihre Kontrollpunkte zu bearbeiten.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Select a Bézier or Hermite row to edit its control points.</source>
        <translation>Eine Bézier- oder Hermite-Zeile auswählen, um ihre Kontrollpunkte zu bearbeiten.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Segment %1, Bézier: control points P0…P3. Moving an end point moves its handle with it.</source>
        <translation>Segment %1, Bézier: Kontrollpunkte P0…P3. Ein verschobener Endpunkt nimmt seinen Griff mit.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Segment %1, Hermite: end points p0, p3 and end tangents t0, t1 (t0 = 3·(P1 − P0)). Moving an end point keeps its tangent.</source>
        <translation>Segment %1, Hermite: Endpunkte p0, p3 und Endtangenten t0, t1 (t0 = 3·(P1 − P0)). Ein verschobener Endpunkt behält seine Tangente.</translation>
    </message>
    <message>
        <location line="+17" />
        <source>%1 %2: a component of the tangent vector, mm</source>
        <translation>%1 %2: eine Komponente des Tangentenvektors, mm</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 %2, mm</source>
        <translation>%1 %2, mm</translation>
    </message>
</context>
<context>
    <name>cam::CursorActions</name>
    <message>
        <location filename="../../src/app/window/cursor_actions.cpp" line="+20" />
        <source>Previous Sample</source>
        <translation>Vorheriger Abtastpunkt</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Next Sample</source>
        <translation>Nächster Abtastpunkt</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Previous Joint</source>
        <translation>Vorheriger Übergang</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Next Joint</source>
        <translation>Nächster Übergang</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Start of the Turn</source>
        <translation>Anfang der Umdrehung</translation>
    </message>
    <message>
        <location line="+2" />
        <source>End of the Turn</source>
        <translation>Ende der Umdrehung</translation>
    </message>
    <message>
        <location line="+3" />
        <source>&amp;Cursor</source>
        <translation>&amp;Cursor</translation>
    </message>
    <message>
        <location line="+10" />
        <source>%1 (with the focus in the contour view or a plot)</source>
        <translation>%1 (mit dem Fokus in der Konturansicht oder einem Diagramm)</translation>
    </message>
</context>
<context>
    <name>cam::DesignTableModel</name>
    <message>
        <location filename="../../src/app/models/design_table_model.cpp" line="+214" />
        <source>How the follower moves over this segment (VDI 2143)</source>
        <translation>Wie sich der Stößel über diesen Abschnitt bewegt (VDI 2143)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Where the segment starts: the previous segment's end</source>
        <translation>Wo der Abschnitt beginnt: das Ende des vorigen</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Cam angle where the segment ends (the last ends at 360°)</source>
        <translation>Kurvenwinkel am Ende des Abschnitts (der letzte endet bei 360°)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>The arm's swing at the segment's end, degrees away from the cam (the last returns to 0)</source>
        <translation>Ausschlag des Hebels am Ende des Abschnitts, in Grad von der Kurve weg (der letzte kehrt auf 0 zurück)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>The follower's lift above the base circle at the segment's end (the last returns to 0)</source>
        <translation>Hub des Stößels über dem Grundkreis am Ende des Abschnitts (der letzte kehrt auf 0 zurück)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Largest velocity as a multiple of lift ÷ duration</source>
        <translation>Größte Geschwindigkeit als Vielfaches von Hub ÷ Dauer</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Largest acceleration as a multiple of lift ÷ duration²</source>
        <translation>Größte Beschleunigung als Vielfaches von Hub ÷ Dauer²</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Largest jerk as a multiple of lift ÷ duration³</source>
        <translation>Größter Ruck als Vielfaches von Hub ÷ Dauer³</translation>
    </message>
    <message>
        <location line="-186" />
        <source>Rest</source>
        <translation>Rast</translation>
    </message>
    <message>
        <location line="+2" />
        <location filename="../../src/app/views/motion_design_panel.cpp" line="+168" />
        <source>Velocity</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <location line="+2" />
        <location filename="../../src/app/views/motion_design_panel.cpp" line="-1" />
        <source>Reversal</source>
        <translation>Umkehr</translation>
    </message>
    <message>
        <location line="+2" />
        <location filename="../../src/app/views/motion_design_panel.cpp" line="-1" />
        <source>Movement</source>
        <translation>Bewegung</translation>
    </message>
    <message>
        <location line="+183" />
        <source>The boundary class the neighbour demands here (VDI 2143): rest (v = 0, a = 0), constant velocity (a = 0), reversal (v = 0) or movement</source>
        <translation>Die Randbedingung, die der Nachbar hier verlangt (VDI 2143): Rast (v = 0, a = 0), konstante Geschwindigkeit (a = 0), Umkehr (v = 0) oder Bewegung</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Where the acceleration changes sign, as a share of the segment (0.5: the symmetric law)</source>
        <translation>Wo die Beschleunigung das Vorzeichen wechselt, als Anteil des Abschnitts (0,5: das symmetrische Gesetz)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Only for the modified sine and the modified trapezoid</source>
        <translation>Nur für die modifizierte Sinuslinie und das modifizierte Beschleunigungstrapez</translation>
    </message>
    <message>
        <location line="+3" />
        <source>SCCA: b is the share of the sine ramps, d of the cosine; the constant acceleration takes the rest (b = d = 0.25: the modified trapezoid)</source>
        <translation>SCCA: b ist der Anteil der Sinusrampen, d der des Kosinus; den Rest nimmt die konstante Beschleunigung (b = d = 0,25: das modifizierte Beschleunigungstrapez)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Only for SCCA</source>
        <translation>Nur für SCCA</translation>
    </message>
    <message>
        <location line="+2" />
        <source>How many points the motion table has; Import Table… reads them from a two-column text file (x and y from 0 to 1)</source>
        <translation>Wie viele Punkte die Bewegungstabelle hat; Tabelle importieren… liest sie aus einer Textdatei mit zwei Spalten (x und y von 0 bis 1)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Only for a motion table</source>
        <translation>Nur für eine Bewegungstabelle</translation>
    </message>
    <message>
        <location line="+2" />
        <source>The lift's slope (v), curvature (a) or its rate (j) per degree of cam angle at the start (0) or the end (1)</source>
        <translation>Steigung (v), Krümmung (a) oder deren Änderung (j) des Hubs je Grad Drehwinkel am Anfang (0) oder Ende (1)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Not a value of this law</source>
        <translation>Kein Wert dieses Gesetzes</translation>
    </message>
    <message>
        <location line="+85" />
        <source>Law</source>
        <translation>Bewegungsgesetz</translation>
    </message>
    <message>
        <location line="+2" />
        <source>From [°]</source>
        <translation>Von [°]</translation>
    </message>
    <message>
        <location line="+2" />
        <source>To [°]</source>
        <translation>Bis [°]</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Lift [%1]</source>
        <translation>Hub [%1]</translation>
    </message>
    <message>
        <location line="+2" />
        <source>v0 [%1/°]</source>
        <translation>v0 [%1/°]</translation>
    </message>
    <message>
        <location line="+2" />
        <source>a0 [%1/°²]</source>
        <translation>a0 [%1/°²]</translation>
    </message>
    <message>
        <location line="+2" />
        <source>v1 [%1/°]</source>
        <translation>v1 [%1/°]</translation>
    </message>
    <message>
        <location line="+2" />
        <source>a1 [%1/°²]</source>
        <translation>a1 [%1/°²]</translation>
    </message>
    <message>
        <location line="+2" />
        <source>j0 [%1/°³]</source>
        <translation>j0 [%1/°³]</translation>
    </message>
    <message>
        <location line="+2" />
        <source>j1 [%1/°³]</source>
        <translation>j1 [%1/°³]</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Points</source>
        <translation>Punkte</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Start</source>
        <translation>Anfang</translation>
    </message>
    <message>
        <location line="+2" />
        <source>End</source>
        <translation>Ende</translation>
    </message>
    <message>
        <location line="+101" />
        <source>Edit %1 of design segment %2</source>
        <translation>%1 von Bewegungsabschnitt %2 ändern</translation>
    </message>
</context>
<context>
    <name>cam::DisplayQuantity</name>
    <message>
        <location filename="../../src/app/widgets/quantity_format.cpp" line="+33" />
        <source>(%1, %2)</source>
        <translation>(%1; %2)</translation>
    </message>
    <message>
        <location filename="../../src/app/widgets/quantity_format.h" line="+65" />
        <location line="+23" />
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <location line="-21" />
        <location line="+20" />
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <location line="-17" />
        <location line="+19" />
        <source>mm/s</source>
        <translation>mm/s</translation>
    </message>
    <message>
        <location line="-18" />
        <location line="+21" />
        <source>mm/s²</source>
        <translation>mm/s²</translation>
    </message>
    <message>
        <location line="-20" />
        <source>mm/s³</source>
        <translation>mm/s³</translation>
    </message>
    <message>
        <location line="+3" />
        <source>s</source>
        <translation>s</translation>
    </message>
    <message>
        <location line="+2" />
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <location line="+3" />
        <source>rad/s</source>
        <translation>rad/s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>rpm</source>
        <translation>U/min</translation>
    </message>
    <message>
        <location line="+9" />
        <location line="+15" />
        <source>°/s</source>
        <translation>°/s</translation>
    </message>
    <message>
        <location line="-10" />
        <location line="+11" />
        <source>°/s²</source>
        <translation>°/s²</translation>
    </message>
    <message>
        <location line="-6" />
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <location line="+1" />
        <source>N·m</source>
        <translation>N·m</translation>
    </message>
    <message>
        <location line="+1" />
        <source>W</source>
        <translation>W</translation>
    </message>
    <message>
        <location line="+1" />
        <source>MPa</source>
        <translation>MPa</translation>
    </message>
    <message>
        <location line="+5" />
        <source>°/s³</source>
        <translation>°/s³</translation>
    </message>
</context>
<context>
    <name>cam::DockLayout</name>
    <message>
        <location filename="../../src/app/window/dock_layout.cpp" line="+93" />
        <source>Control Points</source>
        <translation>Kontrollpunkte</translation>
    </message>
    <message>
        <location line="+32" />
        <source>Machining limits and times (Ctrl+M)</source>
        <translation>Bearbeitungsgrenzen und -zeiten (Strg+M)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Follower</source>
        <translation>Stößel</translation>
    </message>
    <message>
        <location line="+8" />
        <source>The follower and its design checks (Ctrl+L)</source>
        <translation>Der Stößel und seine Auslegungsprüfungen (Strg+L)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Forces</source>
        <translation>Kräfte</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Forces: the spring, the jump speed, torque and contact stress (Ctrl+F)</source>
        <translation>Kräfte: die Feder, die Abhebedrehzahl, Drehmoment und Kontaktpressung (Strg+F)</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Motion Design</source>
        <translation>Bewegungsentwurf</translation>
    </message>
    <message>
        <location line="+8" />
        <source>Design the contour from the follower's motion (Ctrl+D)</source>
        <translation>Die Kontur aus der Bewegung des Stößels entwerfen (Strg+D)</translation>
    </message>
    <message>
        <location line="+176" />
        <source>&lt;b&gt;Segments&lt;/b&gt;: the contour as a table, one row per arc, line or spline piece. Each owns a polar window [φ start, φ end) of the turn; together they cover one turn. Type into a cell and press Enter; Ins inserts, Del deletes. A red cell's tooltip names its problem. F1: the user guide's section on the table.</source>
        <translation>&lt;b&gt;Segmente&lt;/b&gt;: die Kontur als Tabelle, eine Zeile je Bogen, Gerade oder Spline-Stück. Jedes besitzt ein Polarfenster [φ Anfang, φ Ende) der Umdrehung; zusammen decken sie eine Umdrehung ab. In eine Zelle tippen und Eingabe drücken; Einfg fügt ein, Entf löscht. Der Tooltip einer roten Zelle nennt ihr Problem. F1: der Abschnitt des Handbuchs über die Tabelle.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>&lt;b&gt;Joints&lt;/b&gt;: where neighbouring segments meet, with their continuity (position, tangent, curvature) and the jumps of velocity and acceleration. Click a joint to go to it.</source>
        <translation>&lt;b&gt;Übergänge&lt;/b&gt;: wo benachbarte Segmente aufeinandertreffen, mit ihrer Stetigkeit (Lage, Tangente, Krümmung) und den Sprüngen von Geschwindigkeit und Beschleunigung. Ein Klick auf einen Übergang springt dorthin.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>&lt;b&gt;Control Points&lt;/b&gt;: the selected Bézier or Hermite row by value: every control point's x and y, and each end's handle as length and angle. Every edit is one undo step.</source>
        <translation>&lt;b&gt;Kontrollpunkte&lt;/b&gt;: die gewählte Bézier- oder Hermite-Zeile in Zahlen: x und y jedes Kontrollpunkts und der Griff jedes Endes als Länge und Winkel. Jede Änderung ist ein Rückgängig-Schritt.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>&lt;b&gt;Motion&lt;/b&gt;: how fast the cam turns (a period, rpm or rad/s) and how many samples per turn the plots and exports use.</source>
        <translation>&lt;b&gt;Bewegung&lt;/b&gt;: wie schnell sich die Scheibe dreht (Periode, U/min oder rad/s) und wie viele Abtastwerte je Umdrehung Diagramme und Exporte verwenden.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>&lt;b&gt;State at Cursor&lt;/b&gt;: the follower's values at the cursor's instant: angle, segment, r and the polar components of velocity, acceleration and jerk.</source>
        <translation>&lt;b&gt;Zustand am Cursor&lt;/b&gt;: die Werte des Stößels im Augenblick des Cursors: Winkel, Segment, r und die Polarkomponenten von Geschwindigkeit, Beschleunigung und Ruck.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>&lt;b&gt;Machining&lt;/b&gt;: the axes' limits and the tool, and the time it takes to machine the contour with its feed profile.</source>
        <translation>&lt;b&gt;Zerspanung&lt;/b&gt;: die Grenzen der Achsen und das Werkzeug sowie die Zeit, die das Fräsen der Kontur dauert, mit ihrem Vorschubverlauf.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>&lt;b&gt;Path Study&lt;/b&gt;: how evenly the spline segments are parametrised, and their curvature.</source>
        <translation>&lt;b&gt;Bahnstudie&lt;/b&gt;: wie gleichmäßig die Spline-Segmente parametrisiert sind, und ihre Krümmung.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>&lt;b&gt;Follower&lt;/b&gt;: knife, roller or flat face, translating or on a swinging arm, and its checks: pressure angle, curvature, undercut, reach.</source>
        <translation>&lt;b&gt;Stößel&lt;/b&gt;: Schneide, Rolle oder Flachstößel, geradegeführt oder am Schwinghebel, und seine Prüfungen: Druckwinkel, Krümmung, Unterschnitt, Erreichbarkeit.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>&lt;b&gt;Forces&lt;/b&gt;: the follower's mass, its spring, the load and the materials, and what they give over the turn: where the follower leaves the cam, the speed at which it would, the least preload, the torque on the camshaft and the contact stress against the allowable.</source>
        <translation>&lt;b&gt;Kräfte&lt;/b&gt;: die Masse des Stößels, seine Feder, die Last und die Werkstoffe, und was daraus über die Umdrehung folgt: wo der Stößel von der Kurve abhebt, bei welcher Drehzahl er es täte, die kleinste Vorspannkraft, das Drehmoment an der Kurvenwelle und die Kontaktpressung gegenüber der zulässigen.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>&lt;b&gt;Motion Design&lt;/b&gt;: the follower's motion as motion laws over the turn; Synthesize Contour (F6) makes the cam from it.</source>
        <translation>&lt;b&gt;Bewegungsentwurf&lt;/b&gt;: die Bewegung des Stößels als Bewegungsgesetze über der Umdrehung; Kontur synthetisieren (F6) macht daraus die Scheibe.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>&lt;b&gt;Contour&lt;/b&gt;: the cam as seen from above. Drag a square or diamond handle to move a centre, a radius or a spline handle; dragged points snap to centres, joints and the grid (Shift keeps an axis, Alt places freely).</source>
        <translation>&lt;b&gt;Kontur&lt;/b&gt;: die Scheibe von oben gesehen. Einen quadratischen oder rautenförmigen Griff ziehen, um einen Mittelpunkt, einen Radius oder einen Spline-Griff zu verschieben; gezogene Punkte rasten an Mittelpunkten, Übergängen und am Raster ein (Umschalt hält eine Achse fest, Alt platziert frei).</translation>
    </message>
    <message>
        <location line="+3" />
        <source>&lt;b&gt;Plots&lt;/b&gt;: velocity, acceleration and jerk over the angle or the time; the dashed line is the cursor.</source>
        <translation>&lt;b&gt;Diagramme&lt;/b&gt;: Geschwindigkeit, Beschleunigung und Ruck über dem Winkel oder der Zeit; die gestrichelte Linie ist der Cursor.</translation>
    </message>
</context>
<context>
    <name>cam::ExportController</name>
    <message>
        <location filename="../../src/app/window/export_controller.cpp" line="+62" />
        <source>E&amp;xport…</source>
        <translation>E&amp;xportieren…</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Write the profile as CSV, DXF, SVG, G-code or a servo cam table, or a plot as a picture (Ctrl+E)</source>
        <translation>Das Profil als CSV, DXF, SVG, G-Code oder Servo-Kurventabelle schreiben, oder ein Diagramm als Bild (Strg+E)</translation>
    </message>
    <message>
        <location line="+18" />
        <source>Export Plot…</source>
        <translation>Diagramm exportieren…</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Export Lift, Velocity, Acceleration and Jerk on One Sheet…</source>
        <translation>Hub, Geschwindigkeit, Beschleunigung und Ruck auf einem Blatt exportieren…</translation>
    </message>
    <message>
        <location line="+74" />
        <source>Nothing has been computed yet.</source>
        <translation>Es wurde noch nichts berechnet.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>The project has no follower that rides its cam: there is no pressure-angle plot.</source>
        <translation>Das Projekt hat keinen Stößel, der seine Scheibe abtastet: es gibt kein Druckwinkel-Diagramm.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The project has no machining section: there is no %1 plot.</source>
        <translation>Das Projekt hat keinen Bearbeitungsabschnitt: es gibt kein Diagramm „%1“.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>The %1 plot is drawn only while the Machining panel is open (Ctrl+M).</source>
        <translation>Das Diagramm „%1“ wird nur gezeichnet, während das Dock Zerspanung offen ist (Strg+M).</translation>
    </message>
    <message>
        <location line="+8" />
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <location line="+14" />
        <location line="+14" />
        <source>The picture could not be drawn.</source>
        <translation>Das Bild konnte nicht gezeichnet werden.</translation>
    </message>
    <message>
        <location line="+10" />
        <source>PNG image (*.png)</source>
        <translation>PNG-Bild (*.png)</translation>
    </message>
    <message>
        <location line="+0" />
        <source>PDF document (*.pdf)</source>
        <translation>PDF-Dokument (*.pdf)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>SVG drawing (*.svg)</source>
        <translation>SVG-Zeichnung (*.svg)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Export Plot</source>
        <translation>Diagramm exportieren</translation>
    </message>
    <message>
        <location line="+27" />
        <source>%1 plot</source>
        <translation>Diagramm „%1“</translation>
    </message>
    <message>
        <location line="+22" />
        <source>The project has no contour yet: Synthesize (F6) makes it from the design.</source>
        <translation>Das Projekt hat noch keine Kontur: Synthetisieren (F6) erzeugt sie aus dem Entwurf.</translation>
    </message>
    <message>
        <location line="+6" />
        <source>The project has problems; correct them first:
%1</source>
        <translation>Das Projekt hat Fehler; beheben Sie sie zuerst:
%1</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Exporting %1 to %2…</source>
        <translation>Exportiere %1 nach %2…</translation>
    </message>
    <message>
        <location line="+22" />
        <source>Exported %1 to %2 (%3)</source>
        <translation>%1 nach %2 exportiert (%3)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Export failed: %1</source>
        <translation>Export fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Export</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 was not written.</source>
        <translation>%1 wurde nicht geschrieben.</translation>
    </message>
</context>
<context>
    <name>cam::ExportDialog</name>
    <message>
        <location filename="../../src/app/export/export_dialog.cpp" line="+61" />
        <location line="+334" />
        <source>Export</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <location line="-325" />
        <source>&amp;Format:</source>
        <translation>&amp;Format:</translation>
    </message>
    <message>
        <location line="+20" />
        <source>Instants over one turn, equally spaced in time</source>
        <translation>Zeitpunkte über eine Umdrehung, zeitlich gleichabständig</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Samples per turn:</source>
        <translation>&amp;Stützstellen je Umdrehung:</translation>
    </message>
    <message>
        <location line="+14" />
        <location line="+25" />
        <location line="+58" />
        <source>Splines become tangent arc pairs within this distance</source>
        <translation>Splines werden zu tangentialen Bogenpaaren innerhalb dieses Abstands</translation>
    </message>
    <message>
        <location line="-82" />
        <location line="+25" />
        <location line="+58" />
        <source>Spline &amp;tolerance:</source>
        <translation>Spline-&amp;Toleranz:</translation>
    </message>
    <message>
        <location line="-82" />
        <source>One closed &amp;polyline with bulges</source>
        <translation>Eine geschlossene &amp;Polylinie mit Bögen</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Instead of one LINE or ARC entity per segment</source>
        <translation>Statt eines LINE- oder ARC-Elements je Segment</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Bézier and Hermite segments exactly, instead of arc pairs</source>
        <translation>Bézier- und Hermite-Segmente exakt statt als Bogenpaare</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Arc &amp;centres on layer CENTRES</source>
        <translation>Bogen&amp;mittelpunkte auf Layer CENTRES</translation>
    </message>
    <message>
        <location line="+7" />
        <source>The cutter's radius: the path keeps this distance</source>
        <translation>Der Werkzeugradius: die Bahn hält diesen Abstand</translation>
    </message>
    <message>
        <location line="+2" />
        <location line="+18" />
        <source>Tool &amp;radius:</source>
        <translation>Werkzeug&amp;radius:</translation>
    </message>
    <message>
        <location line="-1" />
        <source>The cutter's radius (the project's machining section gives the default)</source>
        <translation>Der Werkzeugradius (vorgegeben aus dem Bearbeitungsabschnitt des Projekts)</translation>
    </message>
    <message>
        <location line="+37" />
        <source>Total depth of cut below the stock's top (Z0)</source>
        <translation>Gesamte Schnitttiefe unter der Rohteiloberkante (Z0)</translation>
    </message>
    <message>
        <location line="-67" />
        <source>Splines as SP&amp;LINE entities</source>
        <translation>Splines als SP&amp;LINE-Elemente</translation>
    </message>
    <message>
        <location line="-17" />
        <source>For a &amp;German spreadsheet: “;” between cells, decimal comma</source>
        <translation>Für eine &amp;deutsche Tabellenkalkulation: „;“ zwischen Zellen, Dezimalkomma</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Excel or LibreOffice in a German locale read a plain CSV as text in one column: this writes 1,5;2,25 instead of 1.5,2.25. Other programs (and camwright-cli) expect the plain form</source>
        <translation>Excel oder LibreOffice mit deutscher Ländereinstellung lesen eine einfache CSV als Text in einer Spalte: dies schreibt 1,5;2,25 statt 1.5,2.25. Andere Programme (und camwright-cli) erwarten die einfache Form</translation>
    </message>
    <message>
        <location line="+21" />
        <source>Tool centre path on layer TOOLPAT&amp;H</source>
        <translation>Werkzeugmittelpunktsbahn auf Layer TOOLPAT&amp;H</translation>
    </message>
    <message>
        <location line="+20" />
        <source>The cutter's radius. The groove's half width (the default) cuts it in one slot pass; a narrower tool, at least a third of that, roughs its centre line and finishes each flank</source>
        <translation>Der Radius des Fräsers. Die halbe Nutbreite (die Vorgabe) fräst die Nut in einem Gang; ein schmaleres Werkzeug, mindestens ein Drittel davon, schruppt ihre Mittellinie und schlichtet jede Flanke</translation>
    </message>
    <message>
        <location line="+9" />
        <source>First plate (the contour)</source>
        <translation>Erste Scheibe (die Kontur)</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Second plate</source>
        <translation>Zweite Scheibe</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Which plate of the conjugate pair this program mills: the second is fitted by arcs within the design's tolerance, as the window draws it</source>
        <translation>Welche Scheibe des Kurvenpaars dieses Programm fräst: Die zweite wird durch Bögen innerhalb der Toleranz des Entwurfs angenähert, wie das Fenster sie zeichnet</translation>
    </message>
    <message>
        <location line="+2" />
        <source>P&amp;late:</source>
        <translation>&amp;Scheibe:</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Feed along the profile; plunges go at half. At most the project's feed limit (Machining dock): %1 mm/min</source>
        <translation>Vorschub entlang des Profils; Eintauchen mit der Hälfte. Höchstens die Vorschubgrenze des Projekts (Dock Zerspanung): %1 mm/min</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Feed along the profile; plunges go at half. The project sets no feed limit (Machining dock): %1 mm/min to start with</source>
        <translation>Vorschub entlang des Profils; Eintauchen mit der Hälfte. Das Projekt setzt keine Vorschubgrenze (Dock Zerspanung): zu Beginn %1 mm/min</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Fee&amp;d:</source>
        <translation>&amp;Vorschub:</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1 mm/min (half the feed)</source>
        <translation>%1 mm/min (halber Vorschub)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Plunge:</source>
        <translation>Eintauchen:</translation>
    </message>
    <message>
        <location line="+3" />
        <source>De&amp;pth:</source>
        <translation>T&amp;iefe:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Step down by</source>
        <translation>&amp;Zustellung je</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Depth of each pass; the last pass reaches the full depth</source>
        <translation>Tiefe je Durchgang; der letzte erreicht die volle Tiefe</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Part contour with cutter &amp;compensation (G41)</source>
        <translation>Werkstückkontur mit Fräser&amp;radiuskorrektur (G41)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Program the profile itself and let the controller offset it by the radius of tool 1, instead of the tool centre path</source>
        <translation>Das Profil selbst programmieren und die Steuerung um den Radius von Werkzeug 1 versetzen lassen, statt der Werkzeugmittelpunktsbahn</translation>
    </message>
    <message>
        <location line="+11" />
        <source>Equidistant master angles over one turn (360° not repeated)</source>
        <translation>Gleichabständige Leitwinkel über eine Umdrehung (360° nicht wiederholt)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Points:</source>
        <translation>&amp;Punkte:</translation>
    </message>
    <message>
        <location line="+8" />
        <source>&amp;Dialect:</source>
        <translation>&amp;Dialekt:</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Motion law (exact)</source>
        <translation>Bewegungsgesetz (exakt)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Contour (follower on the arcs)</source>
        <translation>Kontur (Stößel auf den Bögen)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The design's law is exact; the arc-fitted contour's lift is only C1 (its acceleration steps at every arc joint)</source>
        <translation>Das Gesetz des Entwurfs ist exakt; der Hub der aus Bögen gefügten Kontur ist nur C1 (ihre Beschleunigung springt an jedem Bogenübergang)</translation>
    </message>
    <message>
        <location line="+8" />
        <source>&amp;Source:</source>
        <translation>&amp;Quelle:</translation>
    </message>
    <message>
        <location line="+16" />
        <source>&amp;Plot:</source>
        <translation>&amp;Diagramm:</translation>
    </message>
    <message>
        <location line="+8" />
        <source>&amp;Type:</source>
        <translation>&amp;Art:</translation>
    </message>
    <message>
        <location line="+11" />
        <source>Si&amp;ze (px, pt):</source>
        <translation>&amp;Größe (px, pt):</translation>
    </message>
    <message>
        <location line="+16" />
        <source>&amp;Browse…</source>
        <translation>&amp;Durchsuchen…</translation>
    </message>
    <message>
        <location line="+4" />
        <source>F&amp;ile:</source>
        <translation>Dat&amp;ei:</translation>
    </message>
    <message>
        <location line="+11" />
        <source>&amp;Export</source>
        <translation>&amp;Exportieren</translation>
    </message>
    <message>
        <location line="+140" />
        <source>Name the file to write.</source>
        <translation>Geben Sie die zu schreibende Datei an.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The folder %1 does not exist.</source>
        <translation>Den Ordner %1 gibt es nicht.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 is a folder; name a file in it.</source>
        <translation>%1 ist ein Ordner; geben Sie eine Datei darin an.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>No plot can be drawn yet.</source>
        <translation>Noch kann kein Diagramm gezeichnet werden.</translation>
    </message>
    <message>
        <location line="+32" />
        <source>Measuring the controller's interpolation…</source>
        <translation>Die Interpolation der Steuerung wird gemessen…</translation>
    </message>
    <message>
        <location line="+16" />
        <source>The controller's interpolation (%1) of these %2 points is off the motion by at most %3%4 (at %5°), %6%4/° in velocity and %7%4/°² in acceleration.
Velocity %8 … %9%4/°, acceleration %10 … %11%4/°², jerk %12 … %13%4/°³.</source>
        <translation>Die Interpolation der Steuerung (%1) dieser %2 Punkte weicht höchstens %3%4 (bei %5°) von der Bewegung ab, %6%4/° in der Geschwindigkeit und %7%4/°² in der Beschleunigung.
Geschwindigkeit %8 … %9%4/°, Beschleunigung %10 … %11%4/°², Ruck %12 … %13%4/°³.</translation>
    </message>
</context>
<context>
    <name>cam::FeasibleRegionPlot</name>
    <message>
        <location filename="../../src/app/views/feasible_region_plot.cpp" line="+14" />
        <location line="+36" />
        <source>Offset [mm]</source>
        <translation>Versatz [mm]</translation>
    </message>
    <message>
        <location line="-35" />
        <source>Base radius [mm]</source>
        <translation>Grundkreisradius [mm]</translation>
    </message>
    <message>
        <location line="+2" />
        <source>smallest base radius</source>
        <translation>kleinster Grundkreisradius</translation>
    </message>
    <message>
        <location line="+3" />
        <source>largest base radius</source>
        <translation>größter Grundkreisradius</translation>
    </message>
    <message>
        <location line="+6" />
        <source>smallest cam</source>
        <translation>kleinste Kurvenscheibe</translation>
    </message>
    <message>
        <location line="+4" />
        <source>design</source>
        <translation>Entwurf</translation>
    </message>
    <message>
        <location line="+20" />
        <source>Pivot distance [mm]</source>
        <translation>Abstand des Drehpunkts [mm]</translation>
    </message>
</context>
<context>
    <name>cam::FollowerPanel</name>
    <message>
        <location filename="../../src/app/views/follower_panel.cpp" line="+54" />
        <source>What touches the cam (math.md §7)</source>
        <translation>Was die Kurvenscheibe berührt (math.md §7)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Translating</source>
        <translation>Geradgeführt</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Swinging arm</source>
        <translation>Schwinghebel</translation>
    </message>
    <message>
        <location line="+1" />
        <source>A follower sliding on a line, or swinging on an arm about a pivot</source>
        <translation>Ein Stößel, der auf einer Geraden gleitet oder auf einem Hebel um einen Drehpunkt schwingt</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Radius of the roller</source>
        <translation>Radius der Rolle</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Pivot of the arm, x (in the cam's frame at 0°)</source>
        <translation>Drehpunkt des Hebels, x (im Scheibensystem bei 0°)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Pivot of the arm, y (in the cam's frame at 0°)</source>
        <translation>Drehpunkt des Hebels, y (im Scheibensystem bei 0°)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>From the pivot to the roller centre or the tip</source>
        <translation>Vom Drehpunkt bis zur Rollenmitte oder Spitze</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Counter-clockwise</source>
        <translation>Gegen den Uhrzeigersinn</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Clockwise</source>
        <translation>Im Uhrzeigersinn</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The side of the line pivot → cam centre the arm lies on</source>
        <translation>Die Seite der Linie Drehpunkt → Scheibenmitte, auf der der Hebel liegt</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Largest pressure angle allowed (default: 30° translating, 45° swinging)</source>
        <translation>Größter zulässiger Übertragungs-/Druckwinkel (Vorgabe: 30° geradgeführt, 45° schwingend)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>default</source>
        <translation>Vorgabe</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Spring</source>
        <translation>Feder (Kraftschluss)</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Groove</source>
        <translation>Nut (Formschluss)</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Conjugate plates</source>
        <translation>Kurvenpaar (Formschluss)</translation>
    </message>
    <message>
        <location line="+19" />
        <source>A bell crank: the second arm's angle from the first about the pivot, counter-clockwise positive</source>
        <translation>Ein Winkelhebel: der Winkel des zweiten Arms zum ersten um den Drehpunkt, gegen den Uhrzeigersinn positiv</translation>
    </message>
    <message>
        <location line="+6" />
        <source>A bell crank: from the pivot to the second roller's centre</source>
        <translation>Ein Winkelhebel: vom Drehpunkt zum Mittelpunkt der zweiten Rolle</translation>
    </message>
    <message>
        <location line="+2" />
        <source>The roller's play between the groove's flanks</source>
        <translation>Das Spiel der Rolle zwischen den Flanken der Nut</translation>
    </message>
    <message>
        <location line="+6" />
        <source>The smallest radius the groove's inner flank may come to: the bore or hub plus the wall it needs (none: not checked)</source>
        <translation>Der kleinste Radius, bis zu dem die Innenflanke der Nut reichen darf: Bohrung oder Nabe plus die nötige Wand (keiner: nicht geprüft)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>The largest radius the groove's outer flank may reach: the disc's rim less the wall it needs (none: not checked)</source>
        <translation>Der größte Radius, bis zu dem die Außenflanke der Nut reichen darf: der Rand der Scheibe abzüglich der nötigen Wand (keiner: nicht geprüft)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Type</source>
        <translation>Typ</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Motion</source>
        <translation>Bewegung</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Roller radius</source>
        <translation>Rollenradius</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Offset</source>
        <translation>Versatz</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Pivot x</source>
        <translation>Drehpunkt x</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Pivot y</source>
        <translation>Drehpunkt y</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Pivot</source>
        <translation>Drehpunkt</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Arm length</source>
        <translation>Hebellänge</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Arm side</source>
        <translation>Hebelseite</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Pressure-angle limit</source>
        <translation>Grenze Druckwinkel</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Groove clearance</source>
        <translation>Spiel der Nut</translation>
    </message>
    <message>
        <location line="+1" />
        <source>play </source>
        <translation>Spiel </translation>
    </message>
    <message>
        <location line="+1" />
        <source>Inner land radius</source>
        <translation>Innerer Stegradius</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Outer land radius</source>
        <translation>Äußerer Stegradius</translation>
    </message>
    <message>
        <location line="+1" />
        <source>inner </source>
        <translation>innen </translation>
    </message>
    <message>
        <location line="+1" />
        <source>outer </source>
        <translation>außen </translation>
    </message>
    <message>
        <location line="+1" />
        <source>inner: none</source>
        <translation>innen: keiner</translation>
    </message>
    <message>
        <location line="+1" />
        <source>outer: none</source>
        <translation>außen: keiner</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Closure</source>
        <translation>Schlussart</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Groove lands</source>
        <translation>Stege der Nut</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Second roller's distance</source>
        <translation>Abstand der zweiten Rolle</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Second roller's radius</source>
        <translation>Radius der zweiten Rolle</translation>
    </message>
    <message>
        <location line="+1" />
        <source>distance </source>
        <translation>Abstand </translation>
    </message>
    <message>
        <location line="+1" />
        <source>radius </source>
        <translation>Radius </translation>
    </message>
    <message>
        <location line="+1" />
        <source>Second roller</source>
        <translation>Zweite Rolle</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Second arm's angle</source>
        <translation>Winkel des zweiten Arms</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Second arm's length</source>
        <translation>Länge des zweiten Arms</translation>
    </message>
    <message>
        <location line="+1" />
        <source>angle </source>
        <translation>Winkel </translation>
    </message>
    <message>
        <location line="+1" />
        <source>length </source>
        <translation>Länge </translation>
    </message>
    <message>
        <location line="+1" />
        <source>Second arm</source>
        <translation>Zweiter Arm</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Turning clockwise</source>
        <translation>Dreht im Uhrzeigersinn</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Turning</source>
        <translation>Drehrichtung</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Design checks (click one to go there):</source>
        <translation>Auslegungsprüfungen (Klick springt zur Stelle):</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The follower over the turn: click a line to put the cursor there</source>
        <translation>Der Stößel über eine Umdrehung: Klick auf eine Zeile setzt den Cursor dorthin</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Pressure angle over the turn; dashed: the limit; red: beyond</source>
        <translation>Druckwinkel über eine Umdrehung; gestrichelt: die Grenze; rot: darüber</translation>
    </message>
    <message>
        <location line="+458" />
        <source>Groove: %1 wide (roller radius %2, clearance %3)</source>
        <translation>Nut: %1 breit (Rollenradius %2, Spiel %3)</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Smallest convex radius of the outer flank: %1 at %2</source>
        <translation>Kleinster konvexer Radius der Außenflanke: %1 bei %2</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Smallest concave radius of the outer flank: %1 at %2</source>
        <translation>Kleinster konkaver Radius der Außenflanke: %1 bei %2</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Inner flank nearest the centre: %1 at %2 (land to %3)</source>
        <translation>Innenflanke am nächsten zur Mitte: %1 bei %2 (Steg bis %3)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Inner flank nearest the centre: %1 at %2 (no inner land radius given)</source>
        <translation>Innenflanke am nächsten zur Mitte: %1 bei %2 (kein innerer Stegradius angegeben)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Outer flank farthest from the centre: %1 at %2 (land from %3)</source>
        <translation>Außenflanke am weitesten von der Mitte: %1 bei %2 (Steg ab %3)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Outer flank farthest from the centre: %1 at %2 (no outer land radius given)</source>
        <translation>Außenflanke am weitesten von der Mitte: %1 bei %2 (kein äußerer Stegradius angegeben)</translation>
    </message>
    <message>
        <location line="+8" />
        <source>The second plate cannot be made: %1</source>
        <translation>Die zweite Scheibe lässt sich nicht herstellen: %1</translation>
    </message>
    <message numerus="yes">
        <location line="+9" />
        <source>Second plate: %n arc(s) within %1; the second roller's play from %2 at %3 to %4 at %5</source>
        <translation>
            <numerusform>Zweite Scheibe: %n Bogen innerhalb %1; Spiel der zweiten Rolle von %2 bei %3 bis %4 bei %5</numerusform>
            <numerusform>Zweite Scheibe: %n Bögen innerhalb %1; Spiel der zweiten Rolle von %2 bei %3 bis %4 bei %5</numerusform>
        </translation>
    </message>
    <message>
        <location line="+6" />
        <source>Largest pressure angle at the second roller: %1 at %2 (limit %3)</source>
        <translation>Größter Druckwinkel an der zweiten Rolle: %1 bei %2 (Grenze %3)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Smallest convex radius of the second plate: %1, touched at %2</source>
        <translation>Kleinster konvexer Radius der zweiten Scheibe: %1, berührt bei %2</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Smallest concave radius of the second plate: %1, touched at %2 (second roller radius %3)</source>
        <translation>Kleinster konkaver Radius der zweiten Scheibe: %1, berührt bei %2 (Radius der zweiten Rolle %3)</translation>
    </message>
    <message>
        <location line="-521" />
        <source>Pressure angle [°]</source>
        <translation>Druckwinkel [°]</translation>
    </message>
    <message>
        <location line="+19" />
        <source>Radius of curvature over the turn, positive where convex, negative where hollow; clipped at twice the cam's largest radius (a straight stretch reads as the clip). Blue: the profile; grey: the roller's pitch curve; dashed: the roller's radius and minus the tool's</source>
        <translation>Krümmungsradius über die Umdrehung, positiv wo konvex, negativ wo hohl; begrenzt auf den doppelten größten Radius der Kurvenscheibe (ein gerades Stück liegt auf der Grenze). Blau: das Profil; grau: die Rollenmittelpunktsbahn; gestrichelt: der Rollenradius und minus der Werkzeugradius</translation>
    </message>
    <message>
        <location line="-3" />
        <source>ρ [mm]</source>
        <translation>ρ [mm]</translation>
    </message>
    <message>
        <location line="-150" />
        <source>Offset e of the follower's line of motion from the cam's centre: positive to the left of its direction as seen from the centre, negative to the right (the Turning picture shows it). A positive offset lowers the rise's pressure angle when the cam turns clockwise, a negative one when it turns counter-clockwise; either raises the return's</source>
        <translation>Versatz e der Bewegungslinie des Stößels vom Scheibenmittelpunkt: positiv links seiner Richtung, vom Mittelpunkt aus gesehen, negativ rechts (das Bild Drehrichtung zeigt es). Ein positiver Versatz senkt den Druckwinkel des Hubs, wenn sich die Scheibe im Uhrzeigersinn dreht, ein negativer, wenn sie sich gegen den Uhrzeigersinn dreht; beide erhöhen den des Rückhubs</translation>
    </message>
    <message>
        <location line="+27" />
        <source>What keeps the roller on the cam: a spring; a groove milled into the disc (the contour is its inner flank, the outer flank lies twice the roller radius plus the clearance beyond it); or conjugate plates (a second plate on the same shaft drives a second roller on the same line, across the cam centre)</source>
        <translation>Was die Rolle an der Scheibe hält: eine Feder; eine in die Scheibe gefräste Nut (die Kontur ist ihre Innenflanke, die Außenflanke liegt zweimal den Rollenradius plus das Spiel weiter außen); oder ein Kurvenpaar (eine zweite Scheibe auf derselben Welle treibt eine zweite Rolle auf derselben Geraden, jenseits der Scheibenmitte)</translation>
    </message>
    <message>
        <location line="+6" />
        <source>From the first roller's centre back along the line to the second roller's: it must put the second roller beyond the cam centre at every angle</source>
        <translation>Vom Mittelpunkt der ersten Rolle entlang der Geraden zurück zu dem der zweiten: Die zweite Rolle muss bei jedem Winkel jenseits der Scheibenmitte stehen</translation>
    </message>
    <message>
        <location line="+6" />
        <source>The second roller's radius</source>
        <translation>Der Radius der zweiten Rolle</translation>
    </message>
    <message>
        <location line="+392" />
        <location line="+29" />
        <source>φ [°]</source>
        <translation>φ [°]</translation>
    </message>
    <message>
        <location line="-29" />
        <location line="+30" />
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <location line="+18" />
        <source>No design checks: no contour yet. Synthesize (F6) makes it from the design.</source>
        <translation>Keine Auslegungsprüfungen: noch keine Kontur. Synthetisieren (F6) erzeugt sie aus dem Entwurf.</translation>
    </message>
    <message>
        <location line="+6" />
        <location line="+8" />
        <source>No design checks: %1</source>
        <translation>Keine Auslegungsprüfung: %1</translation>
    </message>
    <message>
        <location line="-7" />
        <source>No design checks: the contour cannot be computed.</source>
        <translation>Keine Auslegungsprüfung: die Kontur lässt sich nicht berechnen.</translation>
    </message>
    <message>
        <location line="+13" />
        <source>The follower cannot ride this cam: %1</source>
        <translation>Der Stößel kann diese Scheibe nicht abtasten: %1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The follower cannot ride this cam.</source>
        <translation>Der Stößel kann diese Scheibe nicht abtasten.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>The seed's knife edge on the radial line: choose a follower to check it.</source>
        <translation>Die Spitze der Vorlage auf der radialen Geraden: wählen Sie einen Stößel, um ihn zu prüfen.</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Largest pressure angle on rise: %1 at %2 (limit %3)</source>
        <translation>Größter Druckwinkel im Hub: %1 bei %2 (Grenze %3)</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Largest pressure angle on return: %1 at %2 (limit %3)</source>
        <translation>Größter Druckwinkel im Rückhub: %1 bei %2 (Grenze %3)</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Largest pressure angle in a dwell: %1 at %2 (limit %3)</source>
        <translation>Größter Druckwinkel in einer Rast: %1 bei %2 (Grenze %3)</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Pressure angle beyond the limit from %1 to %2: up to %3 at %4, %5 too much</source>
        <translation>Druckwinkel über der Grenze von %1 bis %2: bis %3 bei %4, %5 zu viel</translation>
    </message>
    <message>
        <location line="+19" />
        <source>Smallest convex radius of the profile: %1 at %2</source>
        <translation>Kleinster konvexer Radius des Profils: %1 bei %2</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Smallest concave radius of the profile: %1 at %2 (tool radius %3)</source>
        <translation>Kleinster konkaver Radius des Profils: %1 bei %2 (Werkzeugradius %3)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Smallest concave radius of the profile: %1 at %2</source>
        <translation>Kleinster konkaver Radius des Profils: %1 bei %2</translation>
    </message>
    <message>
        <location line="+5" />
        <source>The profile has no concave stretch.</source>
        <translation>Das Profil hat keine hohle Stelle.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Smallest convex radius of the pitch curve: %1 at %2 (roller radius %3)</source>
        <translation>Kleinster konvexer Radius der Rollenmittelpunktsbahn: %1 bei %2 (Rollenradius %3)</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Smallest concave radius of the pitch curve: %1 at %2</source>
        <translation>Kleinster konkaver Radius der Rollenmittelpunktsbahn: %1 bei %2</translation>
    </message>
    <message>
        <location line="-41" />
        <source>The follower cannot reach the profile at %1: it jumps from %2 to %3</source>
        <translation>Der Stößel erreicht das Profil bei %1 nicht: er springt von %2 nach %3</translation>
    </message>
    <message>
        <location line="-164" />
        <source>clockwise (click the picture: the other way)</source>
        <translation>im Uhrzeigersinn (Klick auf das Bild: andersherum)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>counter-clockwise (click the picture: the other way)</source>
        <translation>gegen den Uhrzeigersinn (Klick auf das Bild: andersherum)</translation>
    </message>
    <message>
        <location line="+210" />
        <source>Face width needed: %1</source>
        <translation>Nötige Tellerbreite: %1</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Every check passes.</source>
        <translation>Alle Prüfungen bestanden.</translation>
    </message>
    <message numerus="yes">
        <location line="+1" />
        <source>%n check(s) fail.</source>
        <translation>
            <numerusform>%n Prüfung nicht bestanden.</numerusform>
            <numerusform>%n Prüfungen nicht bestanden.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>cam::ForcesPanel</name>
    <message>
        <location filename="../../src/app/views/forces_panel.cpp" line="+80" />
        <source>Other (typed below)</source>
        <translation>Anderer (unten eingegeben)</translation>
    </message>
    <message>
        <location line="+7" />
        <source>A common material: sets E and Poisson's ratio below (typical room-temperature values; a data sheet's own values can be typed instead)</source>
        <translation>Ein gängiger Werkstoff: setzt E und die Querkontraktionszahl unten (typische Werte bei Raumtemperatur; die Werte eines Datenblatts können stattdessen eingegeben werden)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Cam material</source>
        <translation>Werkstoff der Kurve</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Follower material</source>
        <translation>Werkstoff des Stößels</translation>
    </message>
    <message>
        <location line="+20" />
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <location line="+2" />
        <source> (0 or — : not set)</source>
        <translation> (0 oder —: nicht gesetzt)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>; not set: 1</source>
        <translation>; nicht gesetzt: 1</translation>
    </message>
    <message>
        <location line="+18" />
        <source>Remove Dynamics</source>
        <translation>Dynamik entfernen</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Takes the dynamics out of the project (undo brings them back)</source>
        <translation>Nimmt die Dynamik aus dem Projekt (Rückgängig bringt sie zurück)</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Forces (click one to go there):</source>
        <translation>Kräfte (zum Hinspringen anklicken):</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The forces over the turn: click a line to put the cursor there</source>
        <translation>Die Kräfte über die Umdrehung: eine Zeile anklicken setzt den Cursor dorthin</translation>
    </message>
    <message>
        <location line="+6" />
        <location line="+144" />
        <source>Force [N]</source>
        <translation>Kraft [N]</translation>
    </message>
    <message>
        <location line="-143" />
        <source>Contact normal force over the turn (blue), the law's own (dashed, with a motion design) and the load along the follower's line or the arm's moment (grey); shaded: the follower leaves the cam</source>
        <translation>Normalkraft im Kontakt über die Umdrehung (blau), die des Bewegungsgesetzes selbst (gestrichelt, bei einem Bewegungsentwurf) und die Last längs der Stößelachse oder das Moment am Hebel (grau); schattiert: der Stößel hebt ab</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Torque [N·m]</source>
        <translation>Drehmoment [N·m]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Torque on the camshaft over the turn</source>
        <translation>Drehmoment an der Kurvenwelle über die Umdrehung</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Contact stress [MPa]</source>
        <translation>Kontaktpressung [MPa]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Hertz contact stress over the turn; dashed: the allowable</source>
        <translation>Hertzsche Pressung über die Umdrehung; gestrichelt: die zulässige</translation>
    </message>
    <message>
        <location line="+67" />
        <source>No dynamics: enter the follower's mass and its spring to see the forces, the jump speed and the contact stress.</source>
        <translation>Keine Dynamik: Masse und Feder des Stößels eingeben, um die Kräfte, die Abhebedrehzahl und die Kontaktpressung zu sehen.</translation>
    </message>
    <message>
        <location line="+6" />
        <source>No forces: no contour yet. Synthesize (F6) makes it from the design.</source>
        <translation>Keine Kräfte: noch keine Kontur. Synthetisieren (F6) erzeugt sie aus dem Entwurf.</translation>
    </message>
    <message>
        <location line="+7" />
        <source>No forces: %1</source>
        <translation>Keine Kräfte: %1</translation>
    </message>
    <message>
        <location line="+5" />
        <source>No forces: choose a follower in the Follower dock.</source>
        <translation>Keine Kräfte: im Fenster Stößel einen Stößel wählen.</translation>
    </message>
    <message>
        <location line="+51" />
        <source>φ [°]</source>
        <translation>φ [°]</translation>
    </message>
    <message>
        <location line="+0" />
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <location line="+25" />
        <source>The inner flank carries the load over the whole turn.</source>
        <translation>Die Innenflanke trägt die Last über die ganze Umdrehung.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The first plate carries the load over the whole turn.</source>
        <translation>Die erste Scheibe trägt die Last über die ganze Umdrehung.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>The roller crosses to the outer flank at %1 and back at %2</source>
        <translation>Die Rolle wechselt bei %1 an die Außenflanke und bei %2 zurück</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The second roller takes the load over at %1 and gives it back at %2</source>
        <translation>Die zweite Rolle übernimmt die Last bei %1 und gibt sie bei %2 zurück</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Largest normal force on the outer flank: %1 at %2</source>
        <translation>Größte Normalkraft an der Außenflanke: %1 bei %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Largest normal force on the second roller: %1 at %2</source>
        <translation>Größte Normalkraft an der zweiten Rolle: %1 bei %2</translation>
    </message>
    <message>
        <location line="+8" />
        <source>Largest contact stress on the outer flank: %1 at %2, %3 % of the allowable %4</source>
        <translation>Größte Kontaktpressung an der Außenflanke: %1 bei %2, %3 % der zulässigen %4</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Largest contact stress on the second plate: %1 at %2, %3 % of the allowable %4</source>
        <translation>Größte Kontaktpressung an der zweiten Scheibe: %1 bei %2, %3 % der zulässigen %4</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Largest contact stress on the outer flank: %1 at %2</source>
        <translation>Größte Kontaktpressung an der Außenflanke: %1 bei %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Largest contact stress on the second plate: %1 at %2</source>
        <translation>Größte Kontaktpressung an der zweiten Scheibe: %1 bei %2</translation>
    </message>
    <message>
        <location line="+7" />
        <source>The follower stays on the cam over the whole turn.</source>
        <translation>Der Stößel bleibt über die ganze Umdrehung an der Kurve.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The follower leaves the cam from %1 to %2</source>
        <translation>Der Stößel hebt von %1 bis %2 von der Kurve ab</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Jump speed: %1 at %2 (the cam runs at %3)</source>
        <translation>Abhebedrehzahl: %1 bei %2 (die Kurve läuft mit %3)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>No speed lifts the follower off the cam.</source>
        <translation>Bei keiner Drehzahl hebt der Stößel von der Kurve ab.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Least preload for a safety factor of %1: %2 at %3 (the spring has %4)</source>
        <translation>Kleinste Vorspannkraft für einen Sicherheitsfaktor von %1: %2 bei %3 (die Feder hat %4)</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Largest normal force on the inner flank: %1 at %2</source>
        <translation>Größte Normalkraft an der Innenflanke: %1 bei %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Largest normal force on the first roller: %1 at %2</source>
        <translation>Größte Normalkraft an der ersten Rolle: %1 bei %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Largest normal force: %1 at %2</source>
        <translation>Größte Normalkraft: %1 bei %2</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Peak torque on the camshaft: %1 at %2; RMS %3</source>
        <translation>Größtes Drehmoment an der Kurvenwelle: %1 bei %2; Effektivwert %3</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Peak power: %1</source>
        <translation>Größte Leistung: %1</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Largest contact stress on the inner flank: %1 at %2, %3 % of the allowable %4</source>
        <translation>Größte Kontaktpressung an der Innenflanke: %1 bei %2, %3 % der zulässigen %4</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Largest contact stress on the first plate: %1 at %2, %3 % of the allowable %4</source>
        <translation>Größte Kontaktpressung an der ersten Scheibe: %1 bei %2, %3 % der zulässigen %4</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Largest contact stress: %1 at %2, %3 % of the allowable %4</source>
        <translation>Größte Kontaktpressung: %1 bei %2, %3 % der zulässigen %4</translation>
    </message>
    <message>
        <location line="+8" />
        <source>Largest contact stress on the inner flank: %1 at %2 (no allowable stress given)</source>
        <translation>Größte Kontaktpressung an der Innenflanke: %1 bei %2 (keine zulässige Pressung angegeben)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Largest contact stress on the first plate: %1 at %2 (no allowable stress given)</source>
        <translation>Größte Kontaktpressung an der ersten Scheibe: %1 bei %2 (keine zulässige Pressung angegeben)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Largest contact stress: %1 at %2 (no allowable stress given)</source>
        <translation>Größte Kontaktpressung: %1 bei %2 (keine zulässige Pressung angegeben)</translation>
    </message>
    <message>
        <location line="+8" />
        <source>No contact stress: a knife edge touches the cam at a point.</source>
        <translation>Keine Kontaktpressung: eine Spitze berührt die Kurve in einem Punkt.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>No contact stress: give the contact width and both materials.</source>
        <translation>Keine Kontaktpressung: Kontaktbreite und beide Werkstoffe angeben.</translation>
    </message>
    <message numerus="yes">
        <location line="+9" />
        <source>The normal force jumps at %n joint(s) of the contour, by up to %1 at %2</source>
        <translation>
            <numerusform>Die Normalkraft springt an %n Übergang der Kontur, um bis zu %1 bei %2</numerusform>
            <numerusform>Die Normalkraft springt an %n Übergängen der Kontur, um bis zu %1 bei %2</numerusform>
        </translation>
    </message>
    <message>
        <location line="+21" />
        <source>The contour's normal force differs from the law's by up to %1 at %2</source>
        <translation>Die Normalkraft auf der Kontur weicht von der des Bewegungsgesetzes um bis zu %1 bei %2 ab</translation>
    </message>
    <message>
        <location line="+5" />
        <source>The follower stays on; every force check passes.</source>
        <translation>Der Stößel bleibt an der Kurve; jede Kraftprüfung besteht.</translation>
    </message>
    <message numerus="yes">
        <location line="+1" />
        <source>%n force check(s) fail.</source>
        <translation>
            <numerusform>%n Kraftprüfung schlägt fehl.</numerusform>
            <numerusform>%n Kraftprüfungen schlagen fehl.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>cam::JointsPanel</name>
    <message>
        <location filename="../../src/app/views/joints_panel.cpp" line="+14" />
        <source>Joint</source>
        <translation>Übergang</translation>
    </message>
    <message>
        <location line="+0" />
        <source>φ [°]</source>
        <translation>φ [°]</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Kinematic</source>
        <translation>Kinematisch</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Geometric</source>
        <translation>Geometrisch</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Tangent break [°]</source>
        <translation>Tangentenknick [°]</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Δa_r [mm/s²]</source>
        <translation>Δa_r [mm/s²]</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Δ(d²P/dφ²) rel.</source>
        <translation>Δ(d²P/dφ²) rel.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Continuity in φ, as the follower feels it: C0 position, C1 velocity, C2 acceleration</source>
        <translation>Stetigkeit in φ, wie der Stößel sie spürt: C0 Lage, C1 Geschwindigkeit, C2 Beschleunigung</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Continuity in each curve's own parameter: G1 is a continuous direction whose derivative jumps in length</source>
        <translation>Stetigkeit im eigenen Parameter jeder Kurve: G1 ist eine stetige Richtung, deren Ableitung in der Länge springt</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Jump of the radial acceleration at the joint</source>
        <translation>Sprung der Radialbeschleunigung am Übergang</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Click a joint to put the cursor there</source>
        <translation>Einen Übergang anklicken, um den Cursor dorthin zu setzen</translation>
    </message>
</context>
<context>
    <name>cam::KinematicsPlots</name>
    <message>
        <location filename="../../src/app/views/kinematics_plots.cpp" line="+31" />
        <source>ψ'</source>
        <translation>ψ'</translation>
    </message>
    <message>
        <location line="+0" />
        <source>ψ''</source>
        <translation>ψ''</translation>
    </message>
    <message>
        <location line="+0" />
        <source>ψ'''</source>
        <translation>ψ'''</translation>
    </message>
    <message>
        <location line="+0" />
        <source>ψ</source>
        <translation>ψ</translation>
    </message>
    <message>
        <location line="+3" />
        <source>v</source>
        <translation>v</translation>
    </message>
    <message>
        <location line="+0" />
        <source>a</source>
        <translation>a</translation>
    </message>
    <message>
        <location line="+0" />
        <source>j</source>
        <translation>j</translation>
    </message>
    <message>
        <location line="+0" />
        <source>s</source>
        <translation>s</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Velocity [mm/s]</source>
        <translation>Geschwindigkeit [mm/s]</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Acceleration [mm/s²]</source>
        <translation>Beschleunigung [mm/s²]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Jerk [mm/s³]</source>
        <translation>Ruck [mm/s³]</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Radius r [mm]</source>
        <translation>Radius r [mm]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Velocity v [mm/s]</source>
        <translation>Geschwindigkeit v [mm/s]</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Acceleration a [mm/s²]</source>
        <translation>Beschleunigung a [mm/s²]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Jerk j [mm/s³]</source>
        <translation>Ruck j [mm/s³]</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Lift s [mm]</source>
        <translation>Hub s [mm]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Arm speed ψ' [°/s]</source>
        <translation>Schwinggeschwindigkeit ψ' [°/s]</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Arm acceleration ψ'' [°/s²]</source>
        <translation>Schwingbeschleunigung ψ'' [°/s²]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Arm jerk ψ''' [°/s³]</source>
        <translation>Schwingruck ψ''' [°/s³]</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Arm swing ψ [°]</source>
        <translation>Schwingwinkel ψ [°]</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Radius r</source>
        <translation>Radius r</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Arm swing</source>
        <translation>Schwingwinkel</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Lift</source>
        <translation>Hub</translation>
    </message>
    <message>
        <location line="+8" />
        <source>v_r</source>
        <translation>v_r</translation>
    </message>
    <message>
        <location line="+0" />
        <source>v_φ</source>
        <translation>v_φ</translation>
    </message>
    <message>
        <location line="+0" />
        <source>|v|</source>
        <translation>|v|</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a_r</source>
        <translation>a_r</translation>
    </message>
    <message>
        <location line="+0" />
        <source>a_φ</source>
        <translation>a_φ</translation>
    </message>
    <message>
        <location line="+0" />
        <source>|a|</source>
        <translation>|a|</translation>
    </message>
    <message>
        <location line="+1" />
        <source>j_r</source>
        <translation>j_r</translation>
    </message>
    <message>
        <location line="+0" />
        <source>j_φ</source>
        <translation>j_φ</translation>
    </message>
    <message>
        <location line="+0" />
        <source>|j|</source>
        <translation>|j|</translation>
    </message>
    <message>
        <location line="+1" />
        <source>r</source>
        <translation>r</translation>
    </message>
    <message>
        <location line="+18" />
        <source>law</source>
        <translation>Gesetz</translation>
    </message>
    <message>
        <location line="+3" />
        <source>follower</source>
        <translation>Stößel</translation>
    </message>
    <message>
        <location line="+119" />
        <source>φ [°]</source>
        <translation>φ [°]</translation>
    </message>
    <message>
        <location line="+0" />
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
</context>
<context>
    <name>cam::MachiningPanel</name>
    <message>
        <location filename="../../src/app/views/machining_panel.cpp" line="+46" />
        <source>Add Machining Limits</source>
        <translation>Bearbeitungsgrenzen hinzufügen</translation>
    </message>
    <message>
        <location line="+2" />
        <source>This project has no machining limits yet: add sensible defaults</source>
        <translation>Dieses Projekt hat noch keine Bearbeitungsgrenzen: sinnvolle Vorgaben hinzufügen</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Acceleration</source>
        <translation>Beschleunigung</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Acceleration limit of the %1 axis</source>
        <translation>Beschleunigungsgrenze der %1-Achse</translation>
    </message>
    <message>
        <location line="+6" />
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Acceleration limit of the Z axis (none: only X and Y)</source>
        <translation>Beschleunigungsgrenze der Z-Achse (keine: nur X und Y)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Velocity</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Limit the velocity of each axis</source>
        <translation>Die Geschwindigkeit jeder Achse begrenzen</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Velocity limit of the %1 axis</source>
        <translation>Geschwindigkeitsgrenze der %1-Achse</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Feed ceiling along the path</source>
        <translation>Höchster Vorschub entlang der Bahn</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Radius of the tool: the path is the contour offset by it</source>
        <translation>Werkzeugradius: die Bahn ist die um ihn versetzte Kontur</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Step of the seed method</source>
        <translation>Schrittweite des Ausgangsverfahrens</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Feed</source>
        <translation>Vorschub</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Tool radius</source>
        <translation>Werkzeugradius</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Seed step</source>
        <translation>Schrittweite</translation>
    </message>
    <message>
        <location line="+4" />
        <location line="+8" />
        <source>Seed</source>
        <translation>Ausgangsverfahren</translation>
    </message>
    <message>
        <location line="-8" />
        <location line="+8" />
        <source>Exact stop</source>
        <translation>Genauhalt</translation>
    </message>
    <message>
        <location line="-8" />
        <location line="+8" />
        <source>Optimal</source>
        <translation>Zeitoptimal</translation>
    </message>
    <message>
        <location line="-6" />
        <source>The method whose feed and accelerations are plotted</source>
        <translation>Das Verfahren, dessen Vorschub und Beschleunigungen gezeigt werden</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Plot</source>
        <translation>Diagramm</translation>
    </message>
    <message>
        <location line="+7" />
        <source>The seed document's 1 mm steps from rest to mid-segment, doubled: a legacy estimate that ignores the speed rising within a step</source>
        <translation>Die 1-mm-Schritte des Ausgangsdokuments aus dem Stillstand bis zur Segmentmitte, verdoppelt: eine alte Abschätzung, die den Geschwindigkeitsanstieg innerhalb eines Schritts übergeht</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Rest to rest on every segment</source>
        <translation>Auf jedem Segment aus dem Stillstand in den Stillstand</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Minimum time along the whole path, stopping only at corners</source>
        <translation>Kürzeste Zeit entlang der ganzen Bahn, Halt nur an Ecken</translation>
    </message>
    <message>
        <location line="+15" />
        <location line="+2" />
        <source>path [mm]</source>
        <translation>Bahn [mm]</translation>
    </message>
    <message>
        <location line="-2" />
        <source>feed [mm/s]</source>
        <translation>Vorschub [mm/s]</translation>
    </message>
    <message>
        <location line="+2" />
        <source>axis accel. [mm/s²]</source>
        <translation>Achsbeschl. [mm/s²]</translation>
    </message>
    <message>
        <location line="+91" />
        <location line="+8" />
        <source>Computing…</source>
        <translation>Wird berechnet …</translation>
    </message>
    <message>
        <location line="-6" />
        <source>Machining times need the machine's axis limits.</source>
        <translation>Bearbeitungszeiten brauchen die Achsgrenzen der Maschine.</translation>
    </message>
    <message>
        <location line="+13" />
        <source>No machining time: %1</source>
        <translation>Keine Bearbeitungszeit: %1</translation>
    </message>
    <message>
        <location line="+19" />
        <source>%1 (relative error about %2)</source>
        <translation>%1 (relativer Fehler etwa %2)</translation>
    </message>
    <message>
        <location line="+11" />
        <source>Path %1 (contour offset by the tool radius); optimal plan on %2 grid points; computed in %3</source>
        <translation>Bahn %1 (Kontur um den Werkzeugradius versetzt); zeitoptimaler Plan auf %2 Gitterpunkten; berechnet in %3</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Not converged: the grid limit stopped the refinement first, so these times are estimates: %1.</source>
        <translation>Nicht konvergiert: die Gittergrenze hat die Verfeinerung vorher beendet, diese Zeiten sind daher Schätzungen: %1.</translation>
    </message>
</context>
<context>
    <name>cam::MainWindow</name>
    <message>
        <location filename="../../src/app/mainwindow.cpp" line="+56" />
        <source>The recovery copy could not be written: %1</source>
        <translation>Die Wiederherstellungskopie konnte nicht geschrieben werden: %1</translation>
    </message>
    <message>
        <location line="+158" />
        <source>Cursor at %1</source>
        <translation>Cursor bei %1</translation>
    </message>
    <message>
        <location line="+17" />
        <source>%1[*] — Camwright</source>
        <translation>%1[*] — Camwright</translation>
    </message>
</context>
<context>
    <name>cam::MotionDesignPanel</name>
    <message>
        <location filename="../../src/app/views/motion_design_panel.cpp" line="-62" />
        <source>New Design</source>
        <translation>Neuer Entwurf</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Start from a cycloidal dwell–rise–dwell–return motion (math.md §8) and edit it</source>
        <translation>Mit einer Zykloiden-Bewegung Rast–Hub–Rast–Rückhub beginnen (math.md §8) und sie bearbeiten</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Remove Design</source>
        <translation>Entwurf entfernen</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Remove the motion design from the project (the contour stays)</source>
        <translation>Den Bewegungsentwurf aus dem Projekt entfernen (die Kontur bleibt)</translation>
    </message>
    <message>
        <location line="+8" />
        <source>Radius of the base circle the follower touches at lift 0</source>
        <translation>Radius des Grundkreises, den der Stößel bei Hub 0 berührt</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Smallest</source>
        <translation>Kleinster</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Set the smallest base radius for which the follower passes every check: the pressure angle within its limit on rise and return, no undercut (one undo step)</source>
        <translation>Den kleinsten Grundkreisradius setzen, bei dem der Stößel alle Prüfungen besteht: Druckwinkel im Hub und Rückhub innerhalb der Grenze, kein Unterschnitt (ein Rückgängig-Schritt)</translation>
    </message>
    <message>
        <location line="+280" />
        <source>Best Offset</source>
        <translation>Bester Versatz</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Set the follower's offset that allows the smallest base radius, and that radius, and show the feasible region over base radius × offset (one undo step; a translating knife or roller)</source>
        <translation>Den Versatz des Stößels setzen, der den kleinsten Grundkreisradius erlaubt, und diesen Radius, und den zulässigen Bereich über Grundkreisradius × Versatz zeigen (ein Rückgängig-Schritt; Spitzen- oder Rollenstößel mit Schubbewegung)</translation>
    </message>
    <message>
        <location line="-267" />
        <source>Largest distance of the arc table from the exact profile</source>
        <translation>Größter Abstand der Bogentabelle vom exakten Profil</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Refuse pressure angles beyond the limit</source>
        <translation>Druckwinkel über der Grenze ablehnen</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Synthesize refuses a design whose pressure angle exceeds the follower's limit (otherwise it is only reported)</source>
        <translation>Synthetisieren lehnt einen Entwurf ab, dessen Druckwinkel die Grenze des Stößels überschreitet (sonst wird er nur gemeldet)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Base radius</source>
        <translation>Grundkreisradius</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Tolerance</source>
        <translation>Toleranz</translation>
    </message>
    <message>
        <location line="+31" />
        <source>Split</source>
        <translation>Teilen</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Split the selected segment at its middle: the second half dwells</source>
        <translation>Den gewählten Abschnitt in der Mitte teilen: die zweite Hälfte ist eine Rast</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Delete the selected segment: the one before it takes over its stretch and lift</source>
        <translation>Den gewählten Abschnitt löschen: der vorige übernimmt seinen Bereich und Hub</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Suggest</source>
        <translation>Vorschlagen</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Choose the recommended law for the selected segment from the boundary classes its neighbours demand (VDI 2143, CODESYS SoftMotion's table)</source>
        <translation>Das empfohlene Gesetz für den gewählten Abschnitt aus den Randbedingungen wählen, die seine Nachbarn verlangen (VDI 2143, Tabelle von CODESYS SoftMotion)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Suggest All</source>
        <translation>Alle vorschlagen</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Choose the recommended law for every segment that is not a dwell or a line</source>
        <translation>Das empfohlene Gesetz für jeden Abschnitt wählen, der keine Rast und keine Gerade ist</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Import Table…</source>
        <translation>Tabelle importieren…</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Make the selected segment a motion table from a text file of points: x and y from 0 to 1 in two columns (as Inventor writes them), optionally dy/dx in a third</source>
        <translation>Den gewählten Abschnitt zur Bewegungstabelle aus einer Textdatei mit Punkten machen: x und y von 0 bis 1 in zwei Spalten (wie Inventor sie schreibt), wahlweise dy/dx in einer dritten</translation>
    </message>
    <message>
        <location line="+37" />
        <location line="+12" />
        <source>law</source>
        <translation>Gesetz</translation>
    </message>
    <message>
        <location line="-10" />
        <location line="+13" />
        <source>follower on the contour</source>
        <translation>Stößel auf der Kontur</translation>
    </message>
    <message>
        <location line="+24" />
        <source>Remove design</source>
        <translation>Entwurf entfernen</translation>
    </message>
    <message>
        <location line="+14" />
        <location line="+11" />
        <source>Import Motion Table</source>
        <translation>Bewegungstabelle importieren</translation>
    </message>
    <message>
        <location line="-10" />
        <source>Motion tables (*.txt *.csv *.dat);;All files (*)</source>
        <translation>Bewegungstabellen (*.txt *.csv *.dat);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1: cannot be read</source>
        <translation>%1: kann nicht gelesen werden</translation>
    </message>
    <message>
        <location line="+17" />
        <source>Change base radius</source>
        <translation>Grundkreisradius ändern</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Change tolerance</source>
        <translation>Toleranz ändern</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Change pressure-angle strictness</source>
        <translation>Strenge beim Druckwinkel ändern</translation>
    </message>
    <message>
        <location line="+76" />
        <source>Best Pivot</source>
        <translation>Bester Drehpunkt</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Move the arm's pivot along its line to the cam centre to where it allows the smallest base radius, set that radius, and show the feasible region over base radius × pivot distance (one undo step; the arm keeps its length)</source>
        <translation>Den Drehpunkt des Hebels auf seiner Linie zur Kurvenscheibenmitte dorthin verschieben, wo er den kleinsten Grundkreisradius erlaubt, diesen Radius setzen und den zulässigen Bereich über Grundkreisradius × Drehpunktabstand zeigen (ein Rückgängig-Schritt; der Hebel behält seine Länge)</translation>
    </message>
    <message>
        <location line="+15" />
        <source>Finding the smallest base radius…</source>
        <translation>Kleinster Grundkreisradius wird gesucht …</translation>
    </message>
    <message>
        <location line="-26" />
        <source>The design changed while it was sized: try again.</source>
        <translation>Der Entwurf hat sich während der Suche geändert: bitte erneut versuchen.</translation>
    </message>
    <message>
        <location line="+32" />
        <source>Smallest base radius %1: %2 binds at %3.</source>
        <translation>Kleinster Grundkreisradius %1: %2 begrenzt bei %3.</translation>
    </message>
    <message>
        <location line="+6" />
        <location line="+38" />
        <source>Smallest base radius</source>
        <translation>Kleinster Grundkreisradius</translation>
    </message>
    <message>
        <location line="-14" />
        <source>Smallest base radius %1 at offset %2: %3 binds at %4.</source>
        <translation>Kleinster Grundkreisradius %1 bei Versatz %2: %3 begrenzt bei %4.</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Best offset</source>
        <translation>Bester Versatz</translation>
    </message>
    <message>
        <location line="+23" />
        <source>New design</source>
        <translation>Neuer Entwurf</translation>
    </message>
    <message>
        <location line="+15" />
        <source>Split design segment %1</source>
        <translation>Bewegungsabschnitt %1 teilen</translation>
    </message>
    <message>
        <location line="+21" />
        <source>Delete design segment %1</source>
        <translation>Bewegungsabschnitt %1 löschen</translation>
    </message>
    <message>
        <location line="+111" />
        <source>This project has no motion design. New Design starts one: lay out the follower's motion, then Synthesize makes the contour from it.</source>
        <translation>Dieses Projekt hat keinen Bewegungsentwurf. „Neuer Entwurf“ legt einen an: die Bewegung des Stößels festlegen, dann erzeugt Synthetisieren daraus die Kontur.</translation>
    </message>
    <message numerus="yes">
        <location line="+8" />
        <source>Last synthesis: %n segment(s), at most %1 from the exact profile. The follower on them against the law (%2 angles): lift %3, velocity %4, acceleration %5 (the arcs are only tangent-continuous: the acceleration jumps at their joints).</source>
        <translation>
            <numerusform>Letzte Synthese: %n Abschnitt, höchstens %1 vom exakten Profil. Der Stößel darauf gegenüber dem Gesetz (%2 Winkel): Hub %3, Geschwindigkeit %4, Beschleunigung %5 (Bögen sind nur tangentenstetig: die Beschleunigung springt an ihren Übergängen).</numerusform>
            <numerusform>Letzte Synthese: %n Abschnitte, höchstens %1 vom exakten Profil. Der Stößel darauf gegenüber dem Gesetz (%2 Winkel): Hub %3, Geschwindigkeit %4, Beschleunigung %5 (Bögen sind nur tangentenstetig: die Beschleunigung springt an ihren Übergängen).</numerusform>
        </translation>
    </message>
    <message>
        <location line="+84" />
        <source>The follower on the contour as it is, against the law (%1 samples): lift %2, velocity %3, acceleration %4.</source>
        <translation>Der Stößel auf der jetzigen Kontur gegenüber dem Gesetz (%1 Stützstellen): Hub %2, Geschwindigkeit %3, Beschleunigung %4.</translation>
    </message>
    <message>
        <location line="-55" />
        <source>The design cannot be made: %1</source>
        <translation>Der Entwurf ist nicht herstellbar: %1</translation>
    </message>
    <message>
        <location line="-233" />
        <source>Finding the placement that allows the smallest base radius…</source>
        <translation>Suche die Lage, die den kleinsten Grundkreisradius erlaubt…</translation>
    </message>
    <message>
        <location line="+15" />
        <source>Smallest base radius %1 with the pivot %2 from the cam centre: %3 binds at %4.</source>
        <translation>Kleinster Grundkreisradius %1 mit dem Drehpunkt %2 von der Kurvenscheibenmitte: %3 begrenzt bei %4.</translation>
    </message>
    <message>
        <location line="+11" />
        <source>Best pivot</source>
        <translation>Bester Drehpunkt</translation>
    </message>
    <message>
        <location line="+69" />
        <source>Suggest needs a design that can be evaluated: %1</source>
        <translation>Vorschlagen braucht einen auswertbaren Entwurf: %1</translation>
    </message>
    <message>
        <location line="+8" />
        <source>segment %1: %2</source>
        <translation>Abschnitt %1: %2</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Every law is already the one suggested.</source>
        <translation>Jedes Gesetz ist schon das vorgeschlagene.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Segment %1's law is already the one suggested.</source>
        <translation>Das Gesetz von Abschnitt %1 ist schon das vorgeschlagene.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Suggested %1.</source>
        <translation>Vorgeschlagen: %1.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Suggest laws</source>
        <translation>Gesetze vorschlagen</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Suggest the law of design segment %1</source>
        <translation>Gesetz von Entwurfsabschnitt %1 vorschlagen</translation>
    </message>
    <message>
        <location line="+18" />
        <source>Import a motion table into design segment %1</source>
        <translation>Bewegungstabelle in Entwurfsabschnitt %1 importieren</translation>
    </message>
    <message>
        <location line="+101" />
        <source>The design cannot be drawn at this speed.</source>
        <translation>Der Entwurf lässt sich bei dieser Drehzahl nicht zeichnen.</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Lift [%1]</source>
        <translation>Hub [%1]</translation>
    </message>
    <message>
        <location line="+0" />
        <source>v [%1/s]</source>
        <translation>v [%1/s]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a [%1/s²]</source>
        <translation>a [%1/s²]</translation>
    </message>
    <message>
        <location line="+0" />
        <source>j [%1/s³]</source>
        <translation>j [%1/s³]</translation>
    </message>
    <message>
        <location line="+30" />
        <source>φ [°]</source>
        <translation>φ [°]</translation>
    </message>
    <message>
        <location line="+0" />
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <location line="+21" />
        <source>The follower cannot ride the contour: %1</source>
        <translation>Der Stößel kann die Kontur nicht abfahren: %1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>No contour yet: Synthesize makes it from this design.</source>
        <translation>Noch keine Kontur: Synthetisieren erzeugt sie aus diesem Entwurf.</translation>
    </message>
    <message>
        <location line="-108" />
        <source>Synthesize fits the exact profile with tangent arcs within the tolerance and replaces the contour (one undo step).</source>
        <translation>Synthetisieren nähert das exakte Profil innerhalb der Toleranz durch tangentiale Bögen an und ersetzt die Kontur (ein Rückgängig-Schritt).</translation>
    </message>
</context>
<context>
    <name>cam::MotionPanel</name>
    <message>
        <location filename="../../src/app/views/motion_panel.cpp" line="+24" />
        <source>Turning speed; a positive speed turns the cam clockwise under its follower, a negative one counter-clockwise (the Follower dock pictures the direction: a click there turns the cam round)</source>
        <translation>Drehzahl; eine positive dreht die Scheibe unter ihrem Stößel im Uhrzeigersinn, eine negative gegen den Uhrzeigersinn (das Dock Stößel zeigt die Drehrichtung: ein Klick dort kehrt sie um)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>rad/s</source>
        <translation>rad/s</translation>
    </message>
    <message>
        <location line="+0" />
        <source>rpm</source>
        <translation>U/min</translation>
    </message>
    <message>
        <location line="+0" />
        <source>period [s]</source>
        <translation>Periode [s]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The speed's unit; changing it keeps the physical speed</source>
        <translation>Einheit der Drehgeschwindigkeit; beim Wechsel bleibt die Drehgeschwindigkeit selbst erhalten</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Samples per turn for the plots and exports</source>
        <translation>Abtastpunkte je Umdrehung für Diagramme und Exporte</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Speed</source>
        <translation>Drehgeschwindigkeit</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Samples / turn</source>
        <translation>Punkte / Umdrehung</translation>
    </message>
    <message>
        <location line="+47" />
        <source>ω = %1 · %2
T = %3</source>
        <translation>ω = %1 · %2
T = %3</translation>
    </message>
    <message>
        <location line="+5" />
        <source>The speed must not be 0 (and a period must be positive).</source>
        <translation>Die Drehzahl darf nicht 0 sein (und eine Periode muss positiv sein).</translation>
    </message>
</context>
<context>
    <name>cam::NumberDelegate</name>
    <message>
        <location filename="../../src/app/models/delegates.cpp" line="+55" />
        <source>%1, row %2</source>
        <translation>%1, Zeile %2</translation>
    </message>
</context>
<context>
    <name>cam::NumberSpinBox</name>
    <message>
        <location filename="../../src/app/widgets/number_spin_box.cpp" line="+165" />
        <source>This field</source>
        <translation>Dieses Feld</translation>
    </message>
    <message>
        <location line="+9" />
        <source>%1: %2 is outside %3 … %4; it stays %5.</source>
        <translation>%1: %2 liegt außerhalb %3 … %4; es bleibt %5.</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1: %2 is beyond the largest number there is (about 1.8E308); it stays %3.</source>
        <translation>%1: %2 ist größer als die größte darstellbare Zahl (etwa 1,8E308); es bleibt %3.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1: “%2” is not a number yet; it stays %3.</source>
        <translation>%1: „%2“ ist noch keine Zahl; es bleibt %3.</translation>
    </message>
    <message>
        <location line="+35" />
        <source>%1: “%2” cannot be part of a number: type digits, %3 for decimals and e for a power of ten (1.5e-3).</source>
        <translation>%1: „%2“ kann nicht Teil einer Zahl sein: Ziffern eingeben, %3 für Dezimalstellen und e für eine Zehnerpotenz (1,5e-3).</translation>
    </message>
</context>
<context>
    <name>cam::PathStudyPanel</name>
    <message>
        <location filename="../../src/app/views/path_study_panel.cpp" line="+21" />
        <source>x, y [mm]</source>
        <translation>x, y [mm]</translation>
    </message>
    <message>
        <location line="+0" />
        <source>x', y' [mm]</source>
        <translation>x', y' [mm]</translation>
    </message>
    <message>
        <location line="+0" />
        <source>x'', y'' [mm]</source>
        <translation>x'', y'' [mm]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>quot. − anal.</source>
        <translation>Quot. − anal.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>segment parameter t</source>
        <translation>Segmentparameter t</translation>
    </message>
    <message>
        <location line="+15" />
        <source> analytic</source>
        <translation> analytisch</translation>
    </message>
    <message>
        <location line="+0" />
        <source> quotient</source>
        <translation> Quotient</translation>
    </message>
    <message>
        <location line="+9" />
        <location line="+24" />
        <source>The contour has no Bézier or Hermite segment.</source>
        <translation>Die Kontur hat kein Bézier- oder Hermite-Segment.</translation>
    </message>
    <message>
        <location line="+6" />
        <source>The contour's splines one after another over their parameter t (piece k runs from k to k + 1). Blue x, red y; lines analytic, circles the difference quotients (step h = %1); at the bottom their difference, solid for the first and dashed for the second derivative.</source>
        <translation>Die Splines der Kontur nacheinander über ihrem Parameter t (Stück k läuft von k bis k + 1). Blau x, rot y; Linien analytisch, Kreise die Differenzenquotienten (Schritt h = %1); unten ihre Differenz, durchgezogen für die erste und gestrichelt für die zweite Ableitung.</translation>
    </message>
</context>
<context>
    <name>cam::PlayController</name>
    <message>
        <location filename="../../src/app/window/play_controller.cpp" line="+17" />
        <location line="+40" />
        <source>Play</source>
        <translation>Abspielen</translation>
    </message>
    <message>
        <location line="-36" />
        <source>Turn the cam with the follower riding it (F5)</source>
        <translation>Die Scheibe drehen, der Stößel fährt mit (F5)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Play at this fraction of the cam's real speed</source>
        <translation>Mit diesem Bruchteil der wirklichen Drehzahl abspielen</translation>
    </message>
    <message>
        <location line="+18" />
        <source>Play / Pause</source>
        <translation>Abspielen / Pause</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Play Turns the Cam</source>
        <translation>Abspielen dreht die Scheibe</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Play turns the cam under a follower that stands still, as on the machine; off, the cam stands still and the follower goes round it</source>
        <translation>Abspielen dreht die Scheibe unter dem stillstehenden Stößel, wie auf der Maschine; aus: die Scheibe steht still und der Stößel läuft um sie herum</translation>
    </message>
    <message>
        <location line="+8" />
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
</context>
<context>
    <name>cam::ProjectDocument</name>
    <message>
        <location filename="../../src/app/document/project_document.cpp" line="+23" />
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <location line="+152" />
        <source>… and %1 more</source>
        <translation>… und %1 weitere</translation>
    </message>
</context>
<context>
    <name>cam::ProjectFiles</name>
    <message>
        <location filename="../../src/app/files/project_files.cpp" line="+70" />
        <source>%1 cannot be opened: another file is being opened</source>
        <translation>%1 kann nicht geöffnet werden: Es wird gerade eine andere Datei geöffnet</translation>
    </message>
    <message>
        <location line="+30" />
        <source>Opening</source>
        <translation>Öffnen</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Reading %1 (%2)…</source>
        <translation>%1 wird gelesen (%2)…</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Reading %1…</source>
        <translation>%1 wird gelesen…</translation>
    </message>
    <message>
        <location line="+32" />
        <source>Opening %1 cancelled</source>
        <translation>Öffnen von %1 abgebrochen</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Opening %1 was cancelled</source>
        <translation>Das Öffnen von %1 wurde abgebrochen</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1 cannot be opened:
%2</source>
        <translation>%1 kann nicht geöffnet werden:
%2</translation>
    </message>
    <message>
        <location line="+9" />
        <source>%1 is open in another Camwright window too: a save in either asks before it overwrites the other's</source>
        <translation>%1 ist auch in einem anderen Camwright-Fenster geöffnet: Speichern fragt in beiden, bevor es die Änderungen des anderen überschreibt</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Opened %1</source>
        <translation>%1 geöffnet</translation>
    </message>
    <message numerus="yes">
        <location line="+1" />
        <source>Opened %1 with %n problem(s): listed in the status bar, marked in the table</source>
        <translation>
            <numerusform>%1 mit %n Problem geöffnet: in der Statusleiste aufgeführt, in der Tabelle markiert</numerusform>
            <numerusform>%1 mit %n Problemen geöffnet: in der Statusleiste aufgeführt, in der Tabelle markiert</numerusform>
        </translation>
    </message>
    <message>
        <location line="+13" />
        <source>%1 cannot be saved:
%2</source>
        <translation>%1 kann nicht gespeichert werden:
%2</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1 could not be written: %2</source>
        <translation>%1 konnte nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message numerus="yes">
        <location line="+1" />
        <source>Saved %1 with %n problem(s) still to solve</source>
        <translation>
            <numerusform>%1 mit %n noch offenen Problem gespeichert</numerusform>
            <numerusform>%1 mit %n noch offenen Problemen gespeichert</numerusform>
        </translation>
    </message>
    <message>
        <location line="+10" />
        <location line="+8" />
        <location line="+14" />
        <source>Open Project</source>
        <translation>Projekt öffnen</translation>
    </message>
    <message>
        <location line="-20" />
        <location line="+50" />
        <source>Camwright projects (*.cam.json)</source>
        <translation>Camwright-Projekte (*.cam.json)</translation>
    </message>
    <message>
        <location line="-43" />
        <source>%1 is already open in another Camwright window.</source>
        <translation>%1 ist bereits in einem anderen Camwright-Fenster geöffnet.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Open it here too? Whichever window saves second is asked before it overwrites the other's changes.</source>
        <translation>Auch hier öffnen? Das Fenster, das als zweites speichert, wird gefragt, bevor es die Änderungen des anderen überschreibt.</translation>
    </message>
    <message>
        <location line="+20" />
        <source>Nothing to save: %1 holds this project as it is</source>
        <translation>Nichts zu speichern: %1 enthält das Projekt, wie es ist</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Nothing to save here; %1 was changed on disk by another program or window</source>
        <translation>Hier gibt es nichts zu speichern; %1 wurde auf dem Datenträger von einem anderen Programm oder Fenster geändert</translation>
    </message>
    <message>
        <location line="+8" />
        <location line="+30" />
        <location line="+5" />
        <source>Save Project</source>
        <translation>Projekt speichern</translation>
    </message>
    <message>
        <location line="-27" />
        <location line="+7" />
        <source>Save Project As</source>
        <translation>Projekt speichern unter</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 already exists.
Do you want to replace it?</source>
        <translation>%1 existiert bereits.
Möchten Sie die Datei ersetzen?</translation>
    </message>
    <message>
        <location line="+20" />
        <source>%1 has been changed on disk since this window opened or saved it.</source>
        <translation>%1 wurde auf dem Datenträger geändert, seit dieses Fenster die Datei geöffnet oder gespeichert hat.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Another program or Camwright window has written it. Overwrite its changes with this window's project?</source>
        <translation>Ein anderes Programm oder Camwright-Fenster hat sie geschrieben. Dessen Änderungen mit dem Projekt dieses Fensters überschreiben?</translation>
    </message>
    <message>
        <location line="+2" />
        <source>&amp;Overwrite</source>
        <translation>&amp;Überschreiben</translation>
    </message>
    <message>
        <location line="+37" />
        <source>&amp;Reload</source>
        <translation>Neu &amp;laden</translation>
    </message>
    <message>
        <location line="+2" />
        <source>&amp;Keep This Version</source>
        <translation>Diese &amp;Fassung behalten</translation>
    </message>
    <message>
        <location line="-34" />
        <source>Not saved: %1 keeps the changes made on disk</source>
        <translation>Nicht gespeichert: %1 behält die auf dem Datenträger gemachten Änderungen</translation>
    </message>
    <message>
        <location line="+18" />
        <source>%1 was deleted or moved away on disk; Save writes it again</source>
        <translation>%1 wurde auf dem Datenträger gelöscht oder verschoben; Speichern schreibt die Datei neu</translation>
    </message>
    <message>
        <location line="+4" />
        <location line="+20" />
        <source>File Changed on Disk</source>
        <translation>Datei auf dem Datenträger geändert</translation>
    </message>
    <message>
        <location line="-19" />
        <source>%1 has been changed on disk by another program or window.</source>
        <translation>%1 wurde auf dem Datenträger von einem anderen Programm oder Fenster geändert.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Reload it and discard the unsaved changes made here? Keep them, and Save asks before it overwrites the file.</source>
        <translation>Neu laden und die hier gemachten ungespeicherten Änderungen verwerfen? Werden sie behalten, fragt Speichern, bevor es die Datei überschreibt.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Reload it? Keep this window's version, and Save asks before it overwrites the file.</source>
        <translation>Neu laden? Wird die Fassung dieses Fensters behalten, fragt Speichern, bevor es die Datei überschreibt.</translation>
    </message>
    <message>
        <location line="+20" />
        <source>Unsaved Changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 has unsaved changes. Save them?</source>
        <translation>%1 hat ungespeicherte Änderungen. Speichern?</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Open Example</source>
        <translation>Beispiel öffnen</translation>
    </message>
    <message>
        <location line="+26" />
        <source>Open Recent</source>
        <translation>Zuletzt geöffnet</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 no longer exists; it has been removed from the recent files.</source>
        <translation>%1 existiert nicht mehr und wurde aus der Liste der zuletzt geöffneten Dateien entfernt.</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Recent files cleared</source>
        <translation>Liste der zuletzt geöffneten Dateien geleert</translation>
    </message>
    <message>
        <location line="+14" />
        <source>&amp;Clear Menu</source>
        <translation>Menü &amp;leeren</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Forget the recent files (the files stay where they are)</source>
        <translation>Die Liste der zuletzt geöffneten Dateien leeren (die Dateien selbst bleiben, wo sie sind)</translation>
    </message>
</context>
<context>
    <name>cam::ReadOnlyCells</name>
    <message>
        <location filename="../../src/app/widgets/read_only_cells.cpp" line="+29" />
        <source>%1, row %2</source>
        <translation>%1, Zeile %2</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1 is not typed in.</source>
        <translation>%1 wird nicht eingegeben.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 is not typed in: %2</source>
        <translation>%1 wird nicht eingegeben: %2</translation>
    </message>
</context>
<context>
    <name>cam::RecoveryPrompt</name>
    <message>
        <location filename="../../src/app/files/recovery_prompt.cpp" line="+18" />
        <location line="+31" />
        <source>an untitled project</source>
        <translation>einem unbenannten Projekt</translation>
    </message>
    <message>
        <location line="-28" />
        <location line="+24" />
        <source>Recover Unsaved Changes</source>
        <translation>Ungesicherte Änderungen wiederherstellen</translation>
    </message>
    <message>
        <location line="-23" />
        <source>Camwright did not close properly. Unsaved changes to %1, autosaved %2, can be restored.</source>
        <translation>Camwright wurde nicht ordnungsgemäß beendet. Ungesicherte Änderungen an %1, automatisch gesichert %2, können wiederhergestellt werden.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Restore</source>
        <translation>Wiederherstellen</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Discard</source>
        <translation>Verwerfen</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Later</source>
        <translation>Später</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Later keeps the copy and asks again at the next start.</source>
        <translation>„Später“ behält die Kopie und fragt beim nächsten Start erneut.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>The recovery copy was discarded.</source>
        <translation>Die Wiederherstellungskopie wurde verworfen.</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Restored the unsaved changes of %1: save them to keep them.</source>
        <translation>Ungesicherte Änderungen an %1 wiederhergestellt: speichern, um sie zu behalten.</translation>
    </message>
</context>
<context>
    <name>cam::RoundCornerDialog</name>
    <message>
        <location filename="../../src/app/dialogs/round_corner_dialog.cpp" line="+45" />
        <source>Round Corner</source>
        <translation>Ecke verrunden</translation>
    </message>
    <message>
        <location line="+11" />
        <source>The switch arc's radius: tangent to both neighbours</source>
        <translation>Der Radius des Verrundungsbogens: tangential an beide Nachbarn</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Radius</source>
        <translation>Radius</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Below %1 fits this corner.</source>
        <translation>Unter %1 passt in diese Ecke.</translation>
    </message>
    <message>
        <location line="+7" />
        <source>The corner is concave: a switch arc smaller than the cutter's radius (%1) cannot be cut.</source>
        <translation>Die Ecke ist konkav: ein Verrundungsbogen kleiner als der Werkzeugradius (%1) lässt sich nicht fräsen.</translation>
    </message>
    <message>
        <location line="+12" />
        <source>From the speed at the joint</source>
        <translation>Aus der Geschwindigkeit am Übergang</translation>
    </message>
    <message>
        <location line="+7" />
        <source>The speed V through the corner (the project's feed limit to start with)</source>
        <translation>Die Geschwindigkeit V durch die Ecke (anfangs die Vorschubgrenze des Projekts)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The vector acceleration ACv the machine allows (the smaller of the project's x and y limits to start with)</source>
        <translation>Die Bahnbeschleunigung ACv, die die Maschine erlaubt (anfangs die kleinere der x- und y-Grenzen des Projekts)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The admissible acceleration error vae, a fraction (0.1: 10 %)</source>
        <translation>Der zulässige Beschleunigungsfehler vae als Anteil (0,1: 10 %)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Speed V</source>
        <translation>Geschwindigkeit V</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Acceleration ACv</source>
        <translation>Beschleunigung ACv</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Admissible error vae</source>
        <translation>Zulässiger Fehler vae</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Use This Radius</source>
        <translation>Diesen Radius verwenden</translation>
    </message>
    <message>
        <location line="+42" />
        <source>ρ_min = V² / (vae · ACv) = %1</source>
        <translation>ρ_min = V² / (vae · ACv) = %1</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 is not larger than the cutter's radius %2: the cutter cannot follow it.</source>
        <translation>%1 ist nicht größer als der Werkzeugradius %2: das Werkzeug kann ihm nicht folgen.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 does not fit: below %2 does.</source>
        <translation>%1 passt nicht: unter %2 passt.</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Below the speed's %1: the acceleration through the arc exceeds the machine's by more than vae.</source>
        <translation>Unter den %1 aus der Geschwindigkeit: die Beschleunigung im Bogen übersteigt die der Maschine um mehr als vae.</translation>
    </message>
</context>
<context>
    <name>cam::SegmentTableModel</name>
    <message>
        <location filename="../../src/app/models/segment_table_model.cpp" line="+104" />
        <location line="+52" />
        <source>Arc</source>
        <translation>Bogen</translation>
    </message>
    <message>
        <location line="-52" />
        <location line="+52" />
        <source>Line</source>
        <translation>Gerade</translation>
    </message>
    <message>
        <location line="-52" />
        <location line="+52" />
        <source>Bézier</source>
        <translation>Bézier</translation>
    </message>
    <message>
        <location line="-52" />
        <location line="+52" />
        <source>Hermite</source>
        <translation>Hermite</translation>
    </message>
    <message>
        <location line="-51" />
        <location line="+63" />
        <source>outer</source>
        <translation>außen</translation>
    </message>
    <message>
        <location line="-63" />
        <location line="+63" />
        <source>inner</source>
        <translation>innen</translation>
    </message>
    <message>
        <location line="-56" />
        <source>outer: far intersection of the ray with the circle; inner: near intersection</source>
        <translation>außen: ferner Schnittpunkt des Strahls mit dem Kreis (r_oben); innen: naher Schnittpunkt (r_unten)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>This segment's window follows its end points</source>
        <translation>Das Fenster dieses Segments folgt seinen Endpunkten</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Polar window of this segment, degrees</source>
        <translation>Polares Fenster dieses Segments, Grad</translation>
    </message>
    <message>
        <location line="+11" />
        <source>Drag the handles in the contour view to shape the curve, or type its control points in the Control Points tab.</source>
        <translation>Die Griffe in der Konturansicht ziehen, um die Kurve zu formen, oder ihre Kontrollpunkte im Reiter Kontrollpunkte eingeben.</translation>
    </message>
    <message>
        <location line="+65" />
        <source>What the segment is: an arc of a circle, a line, or a cubic spline piece (Bézier or Hermite)</source>
        <translation>Art des Segments: ein Kreisbogen, eine Strecke oder ein kubisches Spline-Stück (Bézier oder Hermite)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Which of the two points where the follower's ray meets the arc's circle the contour takes: outer, the one farther from the rotation centre (a lobe); inner, the nearer one (a notch, a concave flank)</source>
        <translation>Welchen der beiden Punkte, in denen der Strahl des Stößels den Kreis des Bogens trifft, die Kontur nimmt: außen den vom Drehpunkt weiter entfernten (ein Nocken), innen den näheren (eine Kerbe, eine konkave Flanke)</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Centre of the arc's circle, mm</source>
        <translation>Mittelpunkt des Kreises, mm</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Radius of the arc, mm</source>
        <translation>Radius des Bogens, mm</translation>
    </message>
    <message>
        <location line="+5" />
        <source>End points of the line, mm (counter-clockwise around the centre)</source>
        <translation>Endpunkte der Geraden, mm (gegen den Uhrzeigersinn um das Drehzentrum)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Polar window [φ start, φ end), degrees</source>
        <translation>Polares Fenster [φ Anfang, φ Ende), Grad</translation>
    </message>
    <message>
        <location line="+94" />
        <source>Edit %1 of segment %2</source>
        <translation>%1 von Segment %2 ändern</translation>
    </message>
</context>
<context>
    <name>cam::ShortcutsDialog</name>
    <message>
        <location filename="../../src/app/dialogs/shortcuts_dialog.cpp" line="+16" />
        <source>Keyboard Shortcuts</source>
        <translation>Tastenkürzel</translation>
    </message>
    <message>
        <location line="+15" />
        <source>Edit a cell: type, Enter or Tab to take it</source>
        <translation>Zelle bearbeiten: tippen, Eingabe oder Tab übernimmt</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Cancel a cell's edit</source>
        <translation>Bearbeitung einer Zelle abbrechen</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Step a value live</source>
        <translation>Wert schrittweise ändern</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Up, Down, Page Up, Page Down, wheel</source>
        <translation>Auf, Ab, Bild auf, Bild ab, Mausrad</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Zoom a plot or the contour</source>
        <translation>Diagramm oder Kontur zoomen</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Mouse wheel</source>
        <translation>Mausrad</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Action</source>
        <translation>Aktion</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Keys</source>
        <translation>Tasten</translation>
    </message>
</context>
<context>
    <name>cam::StaleLabel</name>
    <message>
        <location filename="../../src/app/views/stale_label.h" line="+23" />
        <source>No contour yet: Synthesize (F6, in the Motion Design dock) makes it from the design.</source>
        <translation>Noch keine Kontur: Synthetisieren (F6, im Fenster Bewegungsentwurf) erzeugt sie aus dem Entwurf.</translation>
    </message>
    <message numerus="yes">
        <location line="+11" />
        <source> (and %n more)</source>
        <translation>
            <numerusform> (und %n weiterer)</numerusform>
            <numerusform> (und %n weitere)</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2" />
        <source>Not computed: %1%2
Grey: the last computed state, out of date.</source>
        <translation>Nicht berechnet: %1%2
Grau: der zuletzt berechnete Stand, veraltet.</translation>
    </message>
</context>
<context>
    <name>cam::StateReadout</name>
    <message>
        <location filename="../../src/app/views/state_readout.cpp" line="+49" />
        <source>t</source>
        <translation>t</translation>
    </message>
    <message>
        <location line="+0" />
        <source>φ</source>
        <translation>φ</translation>
    </message>
    <message>
        <location line="+0" />
        <source>segment</source>
        <translation>Segment</translation>
    </message>
    <message>
        <location line="+0" />
        <location line="+124" />
        <source>r</source>
        <translation>r</translation>
    </message>
    <message>
        <location line="-124" />
        <location line="+124" />
        <source>v_r</source>
        <translation>v_r</translation>
    </message>
    <message>
        <location line="-123" />
        <location line="+123" />
        <source>v_φ</source>
        <translation>v_φ</translation>
    </message>
    <message>
        <location line="-123" />
        <location line="+123" />
        <source>|v|</source>
        <translation>|v|</translation>
    </message>
    <message>
        <location line="-123" />
        <location line="+124" />
        <source>a_r</source>
        <translation>a_r</translation>
    </message>
    <message>
        <location line="-124" />
        <location line="+124" />
        <source>a_φ</source>
        <translation>a_φ</translation>
    </message>
    <message>
        <location line="-124" />
        <location line="+124" />
        <source>|a|</source>
        <translation>|a|</translation>
    </message>
    <message>
        <location line="-123" />
        <location line="+123" />
        <source>j_r</source>
        <translation>j_r</translation>
    </message>
    <message>
        <location line="-123" />
        <location line="+124" />
        <source>j_φ</source>
        <translation>j_φ</translation>
    </message>
    <message>
        <location line="-124" />
        <location line="+124" />
        <source>|j|</source>
        <translation>|j|</translation>
    </message>
    <message>
        <location line="-124" />
        <source>F_n</source>
        <translation>F_n</translation>
    </message>
    <message>
        <location line="+0" />
        <location line="+169" />
        <source>F</source>
        <translation>F</translation>
    </message>
    <message>
        <location line="-168" />
        <source>T</source>
        <translation>T</translation>
    </message>
    <message>
        <location line="+0" />
        <source>P</source>
        <translation>P</translation>
    </message>
    <message>
        <location line="+0" />
        <source>p_H</source>
        <translation>p_H</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Contact normal force</source>
        <translation>Normalkraft im Kontakt</translation>
    </message>
    <message>
        <location line="+0" />
        <location line="+168" />
        <source>Load along the follower's line of motion</source>
        <translation>Last längs der Bewegungsachse des Stößels</translation>
    </message>
    <message>
        <location line="-167" />
        <source>Torque on the camshaft</source>
        <translation>Drehmoment an der Kurvenwelle</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Power on the camshaft</source>
        <translation>Leistung an der Kurvenwelle</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Hertz contact stress</source>
        <translation>Hertzsche Pressung</translation>
    </message>
    <message>
        <location line="+23" />
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The cursor's time in the turn: type one and press Enter to go there (Up/Down: one sample)</source>
        <translation>Die Zeit des Cursors in der Umdrehung: eine eingeben und mit Enter dorthin gehen (Auf/Ab: ein Abtastpunkt)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The cam's angle at the cursor, 0–360° whichever way it turns: type one and press Enter to go there (Up/Down: one sample)</source>
        <translation>Der Winkel der Kurvenscheibe am Cursor, 0–360° in beiden Drehrichtungen: einen eingeben und mit Enter dorthin gehen (Auf/Ab: ein Abtastpunkt)</translation>
    </message>
    <message>
        <location line="+37" />
        <source>The state at the cursor: move the mouse over a plot, type a time or an angle, or step with the arrow keys in a plot (Shift: to the next joint; Home, End)</source>
        <translation>Der Zustand am Cursor: die Maus über ein Diagramm bewegen, eine Zeit oder einen Winkel eingeben oder mit den Pfeiltasten in einem Diagramm schrittweise gehen (Umschalt: zum nächsten Übergang; Pos1, Ende)</translation>
    </message>
    <message>
        <location line="+30" />
        <source>∞ (straight)</source>
        <translation>∞ (gerade)</translation>
    </message>
    <message>
        <location line="+28" />
        <source>The contour's radius along the ray at the cursor</source>
        <translation>Der Radius der Kontur entlang des Strahls am Cursor</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Velocity of the contour point on the ray: radial, tangential and whole</source>
        <translation>Geschwindigkeit des Konturpunkts auf dem Strahl: radial, tangential und gesamt</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Acceleration of the contour point on the ray: radial, tangential and whole</source>
        <translation>Beschleunigung des Konturpunkts auf dem Strahl: radial, tangential und gesamt</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Jerk of the contour point on the ray: radial, tangential and whole</source>
        <translation>Ruck des Konturpunkts auf dem Strahl: radial, tangential und gesamt</translation>
    </message>
    <message>
        <location line="+1" />
        <source>s</source>
        <translation>s</translation>
    </message>
    <message>
        <location line="+0" />
        <source>v</source>
        <translation>v</translation>
    </message>
    <message>
        <location line="+0" />
        <source>a</source>
        <translation>a</translation>
    </message>
    <message>
        <location line="+0" />
        <source>j</source>
        <translation>j</translation>
    </message>
    <message>
        <location line="+0" />
        <location line="+2" />
        <source>α</source>
        <translation>α</translation>
    </message>
    <message>
        <location line="-2" />
        <location line="+2" />
        <source>ρ</source>
        <translation>ρ</translation>
    </message>
    <message>
        <location line="-1" />
        <source>ψ</source>
        <translation>ψ</translation>
    </message>
    <message>
        <location line="+0" />
        <source>ψ'</source>
        <translation>ψ'</translation>
    </message>
    <message>
        <location line="+0" />
        <source>ψ''</source>
        <translation>ψ''</translation>
    </message>
    <message>
        <location line="+1" />
        <source>ψ'''</source>
        <translation>ψ'''</translation>
    </message>
    <message>
        <location line="+2" />
        <source>The arm's swing away from the cam, from its closest position</source>
        <translation>Der Schwingwinkel des Hebels von der Kurve weg, ab seiner nächsten Stellung</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The follower's lift above its lowest position</source>
        <translation>Der Hub des Stößels über seiner tiefsten Stellung</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The arm's angular velocity, away from the cam positive</source>
        <translation>Die Winkelgeschwindigkeit des Hebels, von der Kurve weg positiv</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The follower's velocity, rising positive</source>
        <translation>Die Geschwindigkeit des Stößels, steigend positiv</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The arm's angular acceleration</source>
        <translation>Die Winkelbeschleunigung des Hebels</translation>
    </message>
    <message>
        <location line="+0" />
        <source>The follower's acceleration</source>
        <translation>Die Beschleunigung des Stößels</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The arm's angular jerk</source>
        <translation>Der Winkelruck des Hebels</translation>
    </message>
    <message>
        <location line="+0" />
        <source>The follower's jerk</source>
        <translation>Der Ruck des Stößels</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The pressure angle: between the contact normal and the follower's direction of motion, positive while it rises</source>
        <translation>Der Druckwinkel: zwischen der Kontaktnormalen und der Bewegungsrichtung des Stößels, positiv beim Steigen</translation>
    </message>
    <message>
        <location line="+2" />
        <source>The profile's radius of curvature at the contact: positive convex, negative concave</source>
        <translation>Der Krümmungsradius des Profils am Kontaktpunkt: positiv konvex, negativ konkav</translation>
    </message>
    <message>
        <location line="+2" />
        <source>The contour segment the follower touches</source>
        <translation>Das Kontursegment, das der Stößel berührt</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The contour segment the ray meets</source>
        <translation>Das Kontursegment, das der Strahl trifft</translation>
    </message>
    <message>
        <location line="+24" />
        <source>M</source>
        <translation>M</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The arm's moment about its pivot</source>
        <translation>Das Moment des Hebels um seinen Drehpunkt</translation>
    </message>
</context>
<context>
    <name>cam::StatusLabels</name>
    <message>
        <location filename="../../src/app/window/status_labels.cpp" line="+37" />
        <source>computing…</source>
        <translation>wird berechnet…</translation>
    </message>
    <message>
        <location line="+8" />
        <source>Valid · no contour yet: Synthesize (F6) makes it</source>
        <translation>Gültig · noch keine Kontur: Synthetisieren (F6) erzeugt sie</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Valid · 1 segment</source>
        <translation>Gültig · 1 Segment</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Valid · %1 segments</source>
        <translation>Gültig · %1 Segmente</translation>
    </message>
    <message>
        <location line="+5" />
        <source>1 problem: </source>
        <translation>1 Fehler: </translation>
    </message>
    <message>
        <location line="+0" />
        <source>%1 problems: </source>
        <translation>%1 Fehler: </translation>
    </message>
    <message>
        <location line="+15" />
        <source>not computed: %1</source>
        <translation>nicht berechnet: %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>no contour yet</source>
        <translation>noch keine Kontur</translation>
    </message>
    <message>
        <location line="+1" />
        <source>not computed: the project has problems</source>
        <translation>nicht berechnet: das Projekt hat Fehler</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Computation failed: %1</source>
        <translation>Berechnung fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1 samples computed in %2</source>
        <translation>%1 Abtastpunkte in %2 berechnet</translation>
    </message>
</context>
<context>
    <name>cam::StressOverlay</name>
    <message>
        <location filename="../../src/app/views/stress_overlay.cpp" line="+92" />
        <source>Contact stress
blue 0 … red %1 (allowable)</source>
        <translation>Kontaktpressung
blau 0 … rot %1 (zulässig)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Contact stress
blue 0 … red %1 (largest)</source>
        <translation>Kontaktpressung
blau 0 … rot %1 (größte)</translation>
    </message>
</context>
<context>
    <name>cam::SynthesisController</name>
    <message>
        <location filename="../../src/app/window/synthesis_controller.cpp" line="+20" />
        <source>S&amp;ynthesize Contour</source>
        <translation>Kontur s&amp;ynthetisieren</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Replace the contour by tangent arcs fitted to the design's exact profile within its tolerance (F6; one undo step)</source>
        <translation>Die Kontur durch tangentiale Bögen ersetzen, die das exakte Profil des Entwurfs innerhalb seiner Toleranz annähern (F6; ein Rückgängig-Schritt)</translation>
    </message>
    <message>
        <location line="+24" />
        <source>Synthesizing the contour…</source>
        <translation>Kontur wird synthetisiert …</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Synthesizing the contour from the design…</source>
        <translation>Die Kontur wird aus dem Entwurf synthetisiert …</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location line="+3" />
        <location line="+38" />
        <source>Synthesize</source>
        <translation>Synthetisieren</translation>
    </message>
    <message>
        <location line="-13" />
        <source>Synthesis cancelled: the contour is unchanged.</source>
        <translation>Synthese abgebrochen: die Kontur ist unverändert.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>The design, follower or speed changed while synthesizing: press Synthesize again.</source>
        <translation>Entwurf, Stößel oder Drehzahl haben sich während der Synthese geändert: bitte erneut synthetisieren.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The contour cannot be made from this design:
%1</source>
        <translation>Aus diesem Entwurf lässt sich keine Kontur erzeugen:
%1</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Synthesized: the contour already is this design's.</source>
        <translation>Synthetisiert: die Kontur ist bereits die dieses Entwurfs.</translation>
    </message>
    <message numerus="yes">
        <location line="+7" />
        <source>Synthesized %n segment(s) within %1 in %2</source>
        <translation>
            <numerusform>%n Abschnitt innerhalb %1 in %2 synthetisiert</numerusform>
            <numerusform>%n Abschnitte innerhalb %1 in %2 synthetisiert</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>cam::TurningPicture</name>
    <message>
        <location filename="../../src/app/views/turning_picture.cpp" line="+32" />
        <source>The cam turns clockwise, seen from the front (the drawing); click to turn it counter-clockwise.</source>
        <translation>Die Scheibe dreht im Uhrzeigersinn, von vorn (auf die Zeichnung) gesehen; klicken, um sie gegen den Uhrzeigersinn drehen zu lassen.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>The cam turns counter-clockwise, seen from the front (the drawing); click to turn it clockwise.</source>
        <translation>Die Scheibe dreht gegen den Uhrzeigersinn, von vorn (auf die Zeichnung) gesehen; klicken, um sie im Uhrzeigersinn drehen zu lassen.</translation>
    </message>
    <message>
        <location line="+2" />
        <source> A period has no sign: counter-clockwise writes the speed in rpm.</source>
        <translation> Eine Periode hat kein Vorzeichen: gegen den Uhrzeigersinn wird die Drehzahl in 1/min geschrieben.</translation>
    </message>
    <message>
        <location line="+3" />
        <source> The follower's line is offset %1 mm to the left of its direction (positive e): this lowers the pressure angle of the rise when the cam turns clockwise and raises it when it turns counter-clockwise.</source>
        <translation> Die Linie des Stößels ist um %1 mm links seiner Richtung versetzt (positives e): das senkt den Druckwinkel des Hubs, wenn sich die Scheibe im Uhrzeigersinn dreht, und erhöht ihn, wenn sie sich gegen den Uhrzeigersinn dreht.</translation>
    </message>
    <message>
        <location line="+4" />
        <source> The follower's line is offset %1 mm to the right of its direction (negative e): this lowers the pressure angle of the rise when the cam turns counter-clockwise and raises it when it turns clockwise.</source>
        <translation> Die Linie des Stößels ist um %1 mm rechts seiner Richtung versetzt (negatives e): das senkt den Druckwinkel des Hubs, wenn sich die Scheibe gegen den Uhrzeigersinn dreht, und erhöht ihn, wenn sie sich im Uhrzeigersinn dreht.</translation>
    </message>
    <message>
        <location line="-5" />
        <source> The follower's line of motion passes through the cam's centre.</source>
        <translation> Die Bewegungslinie des Stößels geht durch die Scheibenmitte.</translation>
    </message>
</context>
<context>
    <name>cam::UserGuide</name>
    <message>
        <location filename="../../src/app/dialogs/user_guide.cpp" line="+11" />
        <source>Camwright User Guide</source>
        <translation>Camwright-Benutzerhandbuch</translation>
    </message>
    <message>
        <location line="+15" />
        <source>user-guide.en.html</source>
        <translation>user-guide.de.html</translation>
    </message>
</context>
<context>
    <name>cam::WindowActions</name>
    <message>
        <location filename="../../src/app/window/window_actions.cpp" line="+54" />
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Undo</source>
        <translation>Rückgängig</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Redo</source>
        <translation>Wiederholen</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Closed %1</source>
        <translation>%1 geschlossen</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Project Name</source>
        <translation>Projektname</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Name of the project:</source>
        <translation>Name des Projekts:</translation>
    </message>
    <message>
        <location line="+17" />
        <source>Fit Windows</source>
        <translation>Fenster anpassen</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Approximate Arc by &amp;Béziers…</source>
        <translation>Bogen durch &amp;Béziers annähern …</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Replace the selected arc by cubic Bézier pieces within a radial error you give</source>
        <translation>Den ausgewählten Bogen durch kubische Bézierstücke innerhalb einer vorgegebenen Radialabweichung ersetzen</translation>
    </message>
    <message>
        <location line="+3" />
        <source>New Contour Through &amp;Points…</source>
        <translation>Neue Kontur durch &amp;Punkte …</translation>
    </message>
    <message>
        <location line="+3" />
        <source>A closed Bézier spline through teach-in points, with automatic handles</source>
        <translation>Ein geschlossener Bézierspline durch Teach-in-Punkte mit automatischen Griffen</translation>
    </message>
    <message>
        <location line="+7" />
        <source>New Contour Through Points</source>
        <translation>Neue Kontur durch Punkte</translation>
    </message>
    <message>
        <location line="+3" />
        <source>R&amp;ound Corner…</source>
        <translation>E&amp;cke verrunden …</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Replace the corner before the selected segment by a tangent switch arc</source>
        <translation>Die Ecke vor dem ausgewählten Segment durch einen tangentialen Schaltbogen ersetzen</translation>
    </message>
    <message>
        <location line="+6" />
        <location line="+7" />
        <location line="+7" />
        <source>Round Corner</source>
        <translation>Ecke verrunden</translation>
    </message>
    <message>
        <location line="-13" />
        <source>Select the segment after the corner to round.</source>
        <translation>Das Segment nach der zu verrundenden Ecke auswählen.</translation>
    </message>
    <message>
        <location line="+16" />
        <source>Tangent &amp;Line to Next Arc</source>
        <translation>&amp;Tangente zum nächsten Bogen</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Join the selected arc to the next one by the line tangent to both; the windows follow from the tangent points</source>
        <translation>Den gewählten Bogen mit dem nächsten durch die Gerade verbinden, die beide berührt; die Fenster ergeben sich aus den Berührpunkten</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Tangent Line</source>
        <translation>Tangente</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Tangent &amp;Arc Through Point</source>
        <translation>Tangentenbo&amp;gen durch Punkt</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Continue the selected segment by a tangent arc through a point you click in the contour view (Esc cancels)</source>
        <translation>Das gewählte Segment durch einen tangentialen Bogen durch einen in der Konturansicht angeklickten Punkt fortsetzen (Esc bricht ab)</translation>
    </message>
    <message>
        <location line="+6" />
        <location line="+14" />
        <source>Tangent Arc</source>
        <translation>Tangentenbogen</translation>
    </message>
    <message>
        <location line="-13" />
        <source>Select the segment the arc continues first.</source>
        <translation>Zuerst das Segment auswählen, das der Bogen fortsetzt.</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Click the point the tangent arc passes through (Esc cancels)</source>
        <translation>Den Punkt anklicken, durch den der Tangentenbogen geht (Esc bricht ab)</translation>
    </message>
    <message>
        <location line="+11" />
        <source>Tangent arc cancelled</source>
        <translation>Tangentenbogen abgebrochen</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Approximate Arc</source>
        <translation>Bogen annähern</translation>
    </message>
    <message>
        <location line="+8" />
        <source>&amp;Lift Plot</source>
        <translation>&amp;Hubdiagramm</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Show the follower's lift (or, in the polar view, the contour's radius r) over the turn above the velocity</source>
        <translation>Den Hub des Stößels (in der Polaransicht den Radius r der Kontur) über der Umdrehung oberhalb der Geschwindigkeit zeigen</translation>
    </message>
    <message>
        <location line="+13" />
        <source>&amp;Polar Kinematics</source>
        <translation>&amp;Polare Kinematik</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Plot the contour's radius r and its polar velocity, acceleration and jerk along the ray instead of the follower's lift, velocity, acceleration and jerk (Ctrl+Shift+P)</source>
        <translation>Den Radius r der Kontur und ihre polare Geschwindigkeit, Beschleunigung und ihren Ruck entlang des Strahls statt Hub, Geschwindigkeit, Beschleunigung und Ruck des Stößels zeigen (Strg+Umschalt+P)</translation>
    </message>
    <message>
        <location line="+9" />
        <source>The plots show the contour's polar kinematics along the ray</source>
        <translation>Die Diagramme zeigen die polare Kinematik der Kontur entlang des Strahls</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The plots show the follower's motion (when the project names one)</source>
        <translation>Die Diagramme zeigen die Bewegung des Stößels (wenn das Projekt einen nennt)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Colour by Contact &amp;Stress</source>
        <translation>Nach Kontakt&amp;pressung färben</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Colour the profile by the Hertz contact stress where the follower touches it (needs the Forces dock's contact width and materials)</source>
        <translation>Das Profil nach der Hertzschen Pressung färben, wo der Stößel es berührt (braucht Kontaktbreite und Werkstoffe im Fenster Kräfte)</translation>
    </message>
    <message>
        <location line="+14" />
        <source>About Camwright</source>
        <translation>Über Camwright</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Keyboard Shortcuts</source>
        <translation>&amp;Tastenkürzel</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Every shortcut of the window</source>
        <translation>Alle Tastenkürzel des Fensters</translation>
    </message>
    <message>
        <location line="+6" />
        <source>User &amp;Guide</source>
        <translation>Benutzer&amp;handbuch</translation>
    </message>
    <message>
        <location line="+4" />
        <source>A short guide to Camwright, opened at the part you are working in: the table, construction, followers, exports, the command line</source>
        <translation>Eine kurze Anleitung zu Camwright, geöffnet bei dem Teil, in dem Sie arbeiten: Tabelle, Konstruktion, Stößel, Exporte, Kommandozeile</translation>
    </message>
    <message>
        <location line="+17" />
        <source>What's &amp;This?</source>
        <translation>&amp;Direkthilfe</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Click a dock or view to learn what it is for</source>
        <translation>Auf ein Dock oder eine Ansicht klicken, um zu erfahren, wofür es da ist</translation>
    </message>
    <message>
        <location line="+81" />
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="+9" />
        <source>&lt;h3&gt;Camwright %1&lt;/h3&gt;&lt;p&gt;Design and inspect cam contours: exact polar kinematics of the follower, design from motion laws, machining time, exports for CAD, CNC and servo drives.&lt;/p&gt;&lt;p&gt;License: GPL-3.0-or-later.&lt;/p&gt;&lt;p&gt;Built with&lt;/p&gt;&lt;ul&gt;&lt;li&gt;Qt %2 (LGPL-3.0)&lt;/li&gt;&lt;li&gt;QCustomPlot %3 (GPL-3.0)&lt;/li&gt;&lt;li&gt;Eigen %4 (MPL-2.0)&lt;/li&gt;&lt;li&gt;JSON for Modern C++ (nlohmann-json) %5 (MIT)&lt;/li&gt;&lt;/ul&gt;</source>
        <translation>&lt;h3&gt;Camwright %1&lt;/h3&gt;&lt;p&gt;Kurvenscheiben entwerfen und prüfen: exakte Polarkinematik des Stößels, Entwurf aus Bewegungsgesetzen, Bearbeitungszeit, Export für CAD, CNC und Servoantriebe.&lt;/p&gt;&lt;p&gt;Lizenz: GPL-3.0-or-later.&lt;/p&gt;&lt;p&gt;Erstellt mit&lt;/p&gt;&lt;ul&gt;&lt;li&gt;Qt %2 (LGPL-3.0)&lt;/li&gt;&lt;li&gt;QCustomPlot %3 (GPL-3.0)&lt;/li&gt;&lt;li&gt;Eigen %4 (MPL-2.0)&lt;/li&gt;&lt;li&gt;JSON for Modern C++ (nlohmann-json) %5 (MIT)&lt;/li&gt;&lt;/ul&gt;</translation>
    </message>
    <message>
        <location line="+33" />
        <source>Project renamed to “%1”</source>
        <translation>Projekt in „%1“ umbenannt</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../../src/app/main.cpp" line="+81" />
        <source>Design and inspect cam contours.</source>
        <translation>Kurvenkonturen entwerfen und prüfen.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>A .cam.json project to open.</source>
        <translation>Ein zu öffnendes .cam.json-Projekt.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Render the main window into FILE.png and exit.</source>
        <translation>Das Hauptfenster in DATEI.png zeichnen und beenden.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Window size for --screenshot.</source>
        <translation>Fenstergröße für --screenshot.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Draw one plot of PROJECT into --out and exit (contour, velocity, acceleration, jerk, feed, axis-acceleration).</source>
        <translation>Ein Diagramm von PROJECT nach --out zeichnen und beenden (contour, velocity, acceleration, jerk, feed, axis-acceleration).</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Picture format for --export-plot: png, pdf or svg (default: the suffix of --out).</source>
        <translation>Bildformat für --export-plot: png, pdf oder svg (Vorgabe: die Endung von --out).</translation>
    </message>
    <message>
        <location line="+5" />
        <source>The file --export-plot writes.</source>
        <translation>Die Datei, die --export-plot schreibt.</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Seconds between recovery copies of unsaved changes (default 30, or the settings' autosave/intervalS).</source>
        <translation>Sekunden zwischen Wiederherstellungskopien ungesicherter Änderungen (Vorgabe 30 oder autosave/intervalS der Einstellungen).</translation>
    </message>
</context>
</TS>

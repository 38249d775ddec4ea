<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de">
<context>
    <name>BrushPresetsPanel</name>
    <message>
        <source>Soft Round</source>
        <translation>Weich rund</translation>
    </message>
    <message>
        <source>Hard Ink</source>
        <translation>Harte Tinte</translation>
    </message>
    <message>
        <source>Chalk</source>
        <translation>Kreide</translation>
    </message>
    <message>
        <source>Spatter</source>
        <translation>Spritzer</translation>
    </message>
    <message>
        <source>Metal Paint</source>
        <translation>Metallfarbe</translation>
    </message>
    <message>
        <source>Rough Matte</source>
        <translation>Rau matt</translation>
    </message>
    <message>
        <source>Eraser Soft</source>
        <translation>Radierer weich</translation>
    </message>
    <message>
        <source>Stabilized Liner</source>
        <translation>Stabilisierter Liner</translation>
    </message>
</context>
<context>
    <name>ToolHints</name>
    <message>
        <source>Brush: drag to paint; Shift+click draws a straight line on from the last stroke; Ctrl+click picks a colour; Alt+drag moves the camera</source>
        <translation>Pinsel: Ziehen malt; Umschalt+Klick zieht eine gerade Linie vom letzten Strich aus; Strg+Klick nimmt eine Farbe auf; Alt+Ziehen bewegt die Kamera</translation>
    </message>
    <message>
        <source>Eraser: drag to bring back the original surface; Shift+click erases a straight line; Alt+drag moves the camera</source>
        <translation>Radierer: Ziehen bringt die ursprüngliche Oberfläche zurück; Umschalt+Klick radiert eine gerade Linie; Alt+Ziehen bewegt die Kamera</translation>
    </message>
    <message>
        <source>Fill: click to fill with the brush colour (options in the Fill panel); Ctrl+click picks a colour</source>
        <translation>Füllen: Klick füllt mit der Pinselfarbe (Optionen im Füllen-Bedienfeld); Strg+Klick nimmt eine Farbe auf</translation>
    </message>
    <message>
        <source>Eyedropper: click to take the painted colour of the surface under the cursor</source>
        <translation>Pipette: Klick übernimmt die gemalte Farbe der Oberfläche unter dem Zeiger</translation>
    </message>
    <message>
        <source>Paint to Hide: paint over regions to hide them and see what lies behind; Shift+H unhides all</source>
        <translation>Zum Ausblenden malen: über Regionen malen, um sie auszublenden und dahinter zu sehen; Umschalt+H blendet alle wieder ein</translation>
    </message>
    <message>
        <source>Pop Up: click to bring the region below the visible one to the front; click again to go deeper (Ctrl+Shift+click with any tool)</source>
        <translation>Hervorholen: Klick holt die Region unter der sichtbaren nach vorn; erneuter Klick geht tiefer (Strg+Umschalt+Klick mit jedem Werkzeug)</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Layer-aware 3D painting of meshes.</source>
        <translation>Ebenenbewusstes 3D-Malen auf Netzen.</translation>
    </message>
    <message>
        <source>file</source>
        <translation>Datei</translation>
    </message>
    <message>
        <source>[file]</source>
        <translation>[Datei]</translation>
    </message>
    <message>
        <source>Where pixel connectivity is computed: auto (the faster here), cpu or gpu.</source>
        <translation>Wo die Pixel-Konnektivität berechnet wird: auto (das hier Schnellere), cpu oder gpu.</translation>
    </message>
    <message>
        <source>The project or model to open (glTF, OBJ, PLY, STL, OFF, ... or builtin:NAME). Without it the trefoil knot opens.</source>
        <translation>Das zu öffnende Projekt oder Modell (glTF, OBJ, PLY, STL, OFF, … oder builtin:NAME). Ohne Angabe öffnet sich der Kleeblattknoten.</translation>
    </message>
</context>
<context>
    <name>ui::BackgroundTask</name>
    <message>
        <source>Not enough memory.</source>
        <translation>Nicht genug Speicher.</translation>
    </message>
</context>
<context>
    <name>ui::BrushPanel</name>
    <message>
        <source>&amp;Radius</source>
        <translation>&amp;Radius</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source>Brush radius on screen ([ and ] change it)</source>
        <translation>Pinselradius auf dem Bildschirm ([ und ] ändern ihn)</translation>
    </message>
    <message>
        <source>&amp;Hardness</source>
        <translation>&amp;Härte</translation>
    </message>
    <message>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <source>0: soft falloff from the centre, 100: a hard edge (Shift+[ and Shift+])</source>
        <translation>0: weicher Verlauf von der Mitte, 100: harte Kante (Umschalt+[ und Umschalt+])</translation>
    </message>
    <message>
        <source>O&amp;pacity</source>
        <translation>&amp;Deckkraft</translation>
    </message>
    <message>
        <source>The most one stroke covers</source>
        <translation>Wie stark ein Strich höchstens deckt</translation>
    </message>
    <message>
        <source>&amp;Flow</source>
        <translation>&amp;Fluss</translation>
    </message>
    <message>
        <source>How much one dab adds towards the opacity</source>
        <translation>Wie viel ein einzelner Tupfer zur Deckkraft beiträgt</translation>
    </message>
    <message>
        <source>&amp;Spacing</source>
        <translation>&amp;Abstand</translation>
    </message>
    <message>
        <source>Distance between dabs, in per cent of the radius</source>
        <translation>Abstand zwischen den Tupfern, in Prozent des Radius</translation>
    </message>
    <message>
        <source>R_max: how far a layer-aware stroke looks for the surface it follows from one dab to the next; 0 chooses it from the radius</source>
        <translation>R_max: wie weit ein ebenenbewusster Strich von einem Tupfer zum nächsten nach der Fläche sucht, der er folgt; 0 leitet den Wert aus dem Radius ab</translation>
    </message>
    <message>
        <source>&amp;Tracking (R_max)</source>
        <translation>&amp;Verfolgung (R_max)</translation>
    </message>
    <message>
        <source>Si&amp;ze</source>
        <translation>&amp;Größe</translation>
    </message>
    <message>
        <source>Pen pressure scales the radius</source>
        <translation>Der Stiftdruck skaliert den Radius</translation>
    </message>
    <message>
        <source>Opa&amp;city</source>
        <translation>Dec&amp;kkraft</translation>
    </message>
    <message>
        <source>Pen pressure scales the opacity</source>
        <translation>Der Stiftdruck skaliert die Deckkraft</translation>
    </message>
    <message>
        <source>Pressure changes</source>
        <translation>Druck ändert</translation>
    </message>
    <message>
        <source>Pressure curve: left, a light touch gives much; right, it takes a firm press</source>
        <translation>Druckkurve: links bewirkt schon leichtes Aufsetzen viel, rechts braucht es festen Druck</translation>
    </message>
    <message>
        <source>Pressure c&amp;urve</source>
        <translation>Druckk&amp;urve</translation>
    </message>
    <message>
        <source>γ %1</source>
        <translation>γ %1</translation>
    </message>
    <message>
        <source>Automatic (%1 px)</source>
        <translation>Automatisch (%1 px)</translation>
    </message>
    <message>
        <source>Base co&amp;lour</source>
        <translation>Grundfar&amp;be</translation>
    </message>
    <message>
        <source>Strokes paint the base colour (the Colour panel&apos;s)</source>
        <translation>Striche malen die Grundfarbe (die des Farbbedienfelds)</translation>
    </message>
    <message>
        <source>R&amp;oughness</source>
        <translation>Rauh&amp;eit</translation>
    </message>
    <message>
        <source>Strokes paint this roughness (0: glossy, 1: matt)</source>
        <translation>Striche malen diese Rauheit (0: glänzend, 1: matt)</translation>
    </message>
    <message>
        <source>&amp;Metallic</source>
        <translation>&amp;Metallisch</translation>
    </message>
    <message>
        <source>Strokes paint this metalness (0: dielectric, 1: metal)</source>
        <translation>Striche malen diesen Metallanteil (0: Nichtmetall, 1: Metall)</translation>
    </message>
</context>
<context>
    <name>ui::BrushPresetsPanel</name>
    <message>
        <source>New from Current</source>
        <translation>Neu aus aktuellem</translation>
    </message>
    <message>
        <source>Save the current brush as a preset</source>
        <translation>Den aktuellen Pinsel als Vorgabe speichern</translation>
    </message>
    <message>
        <source>Rename</source>
        <translation>Umbenennen</translation>
    </message>
    <message>
        <source>Rename the chosen preset</source>
        <translation>Die gewählte Vorgabe umbenennen</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <source>Delete the chosen preset</source>
        <translation>Die gewählte Vorgabe löschen</translation>
    </message>
    <message>
        <source>Import…</source>
        <translation>Importieren…</translation>
    </message>
    <message>
        <source>Add a preset from a .lpbrush file</source>
        <translation>Eine Vorgabe aus einer .lpbrush-Datei hinzufügen</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>Exportieren…</translation>
    </message>
    <message>
        <source>Write the chosen preset to a .lpbrush file</source>
        <translation>Die gewählte Vorgabe in eine .lpbrush-Datei schreiben</translation>
    </message>
    <message>
        <source>%1: cannot be opened (%2)</source>
        <translation>%1: kann nicht geöffnet werden (%2)</translation>
    </message>
    <message>
        <source>%1: too large for a brush preset</source>
        <translation>%1: zu groß für eine Pinselvorgabe</translation>
    </message>
    <message>
        <source>%1: cannot be written (%2)</source>
        <translation>%1: kann nicht geschrieben werden (%2)</translation>
    </message>
    <message>
        <source>New Brush Preset</source>
        <translation>Neue Pinselvorgabe</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Name:</translation>
    </message>
    <message>
        <source>My Brush</source>
        <translation>Mein Pinsel</translation>
    </message>
    <message>
        <source>Import Brush Preset</source>
        <translation>Pinselvorgabe importieren</translation>
    </message>
    <message>
        <source>Brush presets (*.lpbrush);;All files (*)</source>
        <translation>Pinselvorgaben (*.lpbrush);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Export Brush Preset</source>
        <translation>Pinselvorgabe exportieren</translation>
    </message>
    <message>
        <source>Brush presets (*.lpbrush)</source>
        <translation>Pinselvorgaben (*.lpbrush)</translation>
    </message>
</context>
<context>
    <name>ui::BrushTipBox</name>
    <message>
        <source>Round</source>
        <translation>Rund</translation>
    </message>
    <message>
        <source>Round soft</source>
        <translation>Rund weich</translation>
    </message>
    <message>
        <source>Round hard</source>
        <translation>Rund hart</translation>
    </message>
    <message>
        <source>Square</source>
        <translation>Quadrat</translation>
    </message>
    <message>
        <source>Spatter</source>
        <translation>Spritzer</translation>
    </message>
    <message>
        <source>Chalk</source>
        <translation>Kreide</translation>
    </message>
    <message>
        <source>Bristle</source>
        <translation>Borsten</translation>
    </message>
    <message>
        <source>Star</source>
        <translation>Stern</translation>
    </message>
    <message>
        <source>Noise</source>
        <translation>Rauschen</translation>
    </message>
    <message>
        <source>Brush tip</source>
        <translation>Pinselspitze</translation>
    </message>
    <message>
        <source>The tip&apos;s shape: every channel painted is weighted by it</source>
        <translation>Die Form der Spitze: jeder gemalte Kanal wird mit ihr gewichtet</translation>
    </message>
    <message>
        <source>Load T&amp;ip…</source>
        <translation>Spi&amp;tze laden…</translation>
    </message>
    <message>
        <source>Use a PNG or TIFF image as the tip (dark paints); it is kept in the project</source>
        <translation>Ein PNG- oder TIFF-Bild als Spitze verwenden (Dunkles malt); es wird im Projekt gespeichert</translation>
    </message>
    <message>
        <source>Fixed</source>
        <translation>Fest</translation>
    </message>
    <message>
        <source>Follow the stroke</source>
        <translation>Dem Strich folgen</translation>
    </message>
    <message>
        <source>Random</source>
        <translation>Zufällig</translation>
    </message>
    <message>
        <source>How the tip is turned: by the angle, along the stroke&apos;s direction plus the angle, or at random per dab</source>
        <translation>Wie die Spitze gedreht wird: um den Winkel, in Strichrichtung plus Winkel oder zufällig je Tupfer</translation>
    </message>
    <message>
        <source>Tip tur&amp;n</source>
        <translation>Drehu&amp;ng</translation>
    </message>
    <message>
        <source>&amp;Angle</source>
        <translation>W&amp;inkel</translation>
    </message>
    <message>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <source>The tip&apos;s turn, clockwise</source>
        <translation>Die Drehung der Spitze, im Uhrzeigersinn</translation>
    </message>
    <message>
        <source>Size &amp;jitter</source>
        <translation>&amp;Jitter Größe</translation>
    </message>
    <message>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <source>Each dab is up to this much smaller, at random</source>
        <translation>Jeder Tupfer ist zufällig bis zu so viel kleiner</translation>
    </message>
    <message>
        <source>Opacit&amp;y jitter</source>
        <translation>Jitter De&amp;ckkraft</translation>
    </message>
    <message>
        <source>Each dab is up to this much more transparent, at random</source>
        <translation>Jeder Tupfer ist zufällig bis zu so viel durchsichtiger</translation>
    </message>
    <message>
        <source>An&amp;gle jitter</source>
        <translation>Jitter Winke&amp;l</translation>
    </message>
    <message>
        <source>Each dab turns up to this far either way, at random</source>
        <translation>Jeder Tupfer dreht sich zufällig bis zu so weit in jede Richtung</translation>
    </message>
    <message>
        <source>Scatt&amp;er</source>
        <translation>&amp;Streuung</translation>
    </message>
    <message>
        <source>Each dab moves up to this far from the stroke, in per cent of the radius</source>
        <translation>Jeder Tupfer rückt bis zu so weit vom Strich ab, in Prozent des Radius</translation>
    </message>
    <message>
        <source>The random jitter&apos;s seed: the same seed paints the same stroke again</source>
        <translation>Startwert des Zufalls: derselbe Startwert malt denselben Strich noch einmal</translation>
    </message>
    <message>
        <source>See&amp;d</source>
        <translation>Start&amp;wert</translation>
    </message>
    <message>
        <source>Loaded</source>
        <translation>Geladen</translation>
    </message>
    <message>
        <source>Load Brush Tip</source>
        <translation>Pinselspitze laden</translation>
    </message>
    <message>
        <source>Images (*.png *.tif *.tiff);;All files (*)</source>
        <translation>Bilder (*.png *.tif *.tiff);;Alle Dateien (*)</translation>
    </message>
</context>
<context>
    <name>ui::BrushToolBar</name>
    <message>
        <source>Brush colour</source>
        <translation>Pinselfarbe</translation>
    </message>
    <message>
        <source>&amp;Radius</source>
        <translation>&amp;Radius</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source>&amp;Hardness</source>
        <translation>&amp;Härte</translation>
    </message>
    <message>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <source>O&amp;pacity</source>
        <translation>&amp;Deckkraft</translation>
    </message>
    <message>
        <source>The most one stroke covers</source>
        <translation>Wie stark ein Strich höchstens deckt</translation>
    </message>
    <message>
        <source>Paint &amp;into</source>
        <translation>Malen &amp;in</translation>
    </message>
    <message>
        <source>Where paint goes: a texture (meshes with UVs) or vertex colours. Changing it starts the painting afresh.</source>
        <translation>Wohin die Farbe geht: in eine Textur (Netze mit UVs) oder in Vertexfarben. Ein Wechsel beginnt das Bemalen von vorn.</translation>
    </message>
    <message>
        <source>Vertex colours</source>
        <translation>Vertexfarben</translation>
    </message>
    <message>
        <source>Brush Colour</source>
        <translation>Pinselfarbe</translation>
    </message>
    <message>
        <source>Brush radius on screen ([ smaller, ] larger)</source>
        <translation>Pinselradius auf dem Bildschirm ([ kleiner, ] größer)</translation>
    </message>
    <message>
        <source>0: soft falloff from the centre, 100: a hard edge (Shift+[ softer, Shift+] harder)</source>
        <translation>0: weicher Verlauf von der Mitte, 100: harte Kante (Umschalt+[ weicher, Umschalt+] härter)</translation>
    </message>
    <message>
        <source>Brush Bar</source>
        <translation>Pinselleiste</translation>
    </message>
    <message>
        <source>This model has no texture coordinates (UVs): a texture gets an automatic UV layout; vertex colours follow its vertices.</source>
        <translation>Dieses Modell hat keine Texturkoordinaten (UVs): Eine Textur bekommt ein automatisches UV-Layout; Vertexfarben folgen seinen Vertices.</translation>
    </message>
    <message>
        <source>Texture %1 × %1, automatic UVs</source>
        <translation>Textur %1 × %1, automatische UVs</translation>
    </message>
    <message>
        <source>Texture %1</source>
        <translation>Textur %1</translation>
    </message>
    <message>
        <source>Texture %1, automatic UVs</source>
        <translation>Textur %1, automatische UVs</translation>
    </message>
    <message>
        <source>A new texture of %1 × %1 texels over an automatic UV layout: places that share UVs are painted apart.</source>
        <translation>Eine neue Textur mit %1 × %1 Texeln über einem automatischen UV-Layout: Stellen, die sich UVs teilen, werden getrennt bemalt.</translation>
    </message>
    <message>
        <source>%1 × %2</source>
        <translation>%1 × %2</translation>
    </message>
    <message>
        <source>%1 – %2</source>
        <translation>%1 – %2</translation>
    </message>
    <message>
        <source>material %1</source>
        <translation>Material %1</translation>
    </message>
    <message>
        <source>%1: %2 (its base colour texture)</source>
        <translation>%1: %2 (seine Grundfarbtextur)</translation>
    </message>
    <message>
        <source>%1: %2 (a new texture)</source>
        <translation>%1: %2 (eine neue Textur)</translation>
    </message>
    <message>
        <source>Painted into:</source>
        <translation>Bemalt wird:</translation>
    </message>
    <message numerus="yes">
        <source>… and %n more material(s)</source>
        <translation>
            <numerusform>… und %n weiteres Material</numerusform>
            <numerusform>… und %n weitere Materialien</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ui::ColorPanel</name>
    <message>
        <source>Foreground colour: the brush paints with it</source>
        <translation>Vordergrundfarbe: mit ihr malt der Pinsel</translation>
    </message>
    <message>
        <source>Foreground Colour</source>
        <translation>Vordergrundfarbe</translation>
    </message>
    <message>
        <source>Background colour (X swaps it with the foreground)</source>
        <translation>Hintergrundfarbe (X tauscht sie mit der Vordergrundfarbe)</translation>
    </message>
    <message>
        <source>Swap foreground and background colours (X)</source>
        <translation>Vorder- und Hintergrundfarbe tauschen (X)</translation>
    </message>
    <message>
        <source>&amp;Hex</source>
        <translation>&amp;Hex</translation>
    </message>
    <message>
        <source>The foreground colour as #rrggbb (sRGB)</source>
        <translation>Die Vordergrundfarbe als #rrggbb (sRGB)</translation>
    </message>
    <message>
        <source>Recent colours</source>
        <translation>Zuletzt verwendete Farben</translation>
    </message>
    <message>
        <source>Background Colour</source>
        <translation>Hintergrundfarbe</translation>
    </message>
</context>
<context>
    <name>ui::DepthLayersBuilder</name>
    <message>
        <source>not enough memory for the depth layers of this view</source>
        <translation>nicht genug Speicher für die Tiefenebenen dieser Ansicht</translation>
    </message>
    <message>
        <source>not enough memory for the symmetric views</source>
        <translation>nicht genug Speicher für die symmetrischen Ansichten</translation>
    </message>
</context>
<context>
    <name>ui::DepthLayersPanel</name>
    <message>
        <source>The whole view, front to back</source>
        <translation>Die ganze Ansicht, von vorn nach hinten</translation>
    </message>
    <message>
        <source>Depth layer %1
Fragments: %2
Regions: %3</source>
        <translation>Tiefenebene %1
Fragmente: %2
Regionen: %3</translation>
    </message>
    <message>
        <source>Show depth layer %1 alone</source>
        <translation>Tiefenebene %1 allein zeigen</translation>
    </message>
    <message>
        <source>Depth layers appear when the view stays still.</source>
        <translation>Die Tiefenebenen erscheinen, sobald die Ansicht stillsteht.</translation>
    </message>
    <message>
        <source>Click a depth layer to see it alone; “All depth layers” shows the whole view.</source>
        <translation>Klicken Sie auf eine Tiefenebene, um sie allein zu sehen; „Alle Tiefenebenen“ zeigt die ganze Ansicht.</translation>
    </message>
    <message>
        <source>All depth layers
Depth layers: %1
Regions: %2</source>
        <translation>Alle Tiefenebenen
Tiefenebenen: %1
Regionen: %2</translation>
    </message>
</context>
<context>
    <name>ui::FillPanel</name>
    <message>
        <source>Region under the cursor</source>
        <translation>Region unter dem Zeiger</translation>
    </message>
    <message>
        <source>Connected surface</source>
        <translation>Zusammenhängende Fläche</translation>
    </message>
    <message>
        <source>Similar colour</source>
        <translation>Ähnliche Farbe</translation>
    </message>
    <message>
        <source>The segmented region clicked in this view, including the part of it hidden behind other surfaces</source>
        <translation>Die angeklickte Region der Segmentierung dieser Ansicht, einschließlich ihres hinter anderen Flächen verborgenen Teils</translation>
    </message>
    <message>
        <source>Everything connected to the clicked surface in the mesh, seen or not, from any side</source>
        <translation>Alles, was im Netz mit der angeklickten Fläche verbunden ist, ob sichtbar oder nicht, von jeder Seite</translation>
    </message>
    <message>
        <source>The surface around the clicked point whose colour is within the tolerance of the colour there</source>
        <translation>Die Fläche um den angeklickten Punkt, deren Farbe innerhalb der Toleranz der Farbe dort liegt</translation>
    </message>
    <message>
        <source>What a click with the Fill tool fills</source>
        <translation>Was ein Klick mit dem Füllwerkzeug füllt</translation>
    </message>
    <message>
        <source>Colour tolerance</source>
        <translation>Farbtoleranz</translation>
    </message>
    <message>
        <source>How far a colour may differ from the clicked one and still be filled (in any channel): 0 % takes only the very same colour</source>
        <translation>Wie weit eine Farbe von der angeklickten abweichen darf und trotzdem gefüllt wird (in jedem Kanal): 0 % nimmt nur genau dieselbe Farbe</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>&amp;Fill:</source>
        <translation>&amp;Füllen:</translation>
    </message>
    <message>
        <source>&amp;Tolerance:</source>
        <translation>&amp;Toleranz:</translation>
    </message>
</context>
<context>
    <name>ui::HiddenRegionsPanel</name>
    <message>
        <source>Paint with the Hide tool (H) to hide regions and see behind them.</source>
        <translation>Malen Sie mit dem Ausblenden-Werkzeug (H), um Regionen auszublenden und dahinter zu sehen.</translation>
    </message>
    <message>
        <source>&amp;Unhide</source>
        <translation>&amp;Einblenden</translation>
    </message>
    <message>
        <source>Show the selected regions again</source>
        <translation>Die ausgewählten Regionen wieder zeigen</translation>
    </message>
    <message>
        <source>Unhide &amp;All</source>
        <translation>&amp;Alle einblenden</translation>
    </message>
    <message numerus="yes">
        <source>Region %1 · depth layer %2 · %n pixel(s)</source>
        <translation>
            <numerusform>Region %1 · Tiefenebene %2 · %n Pixel</numerusform>
            <numerusform>Region %1 · Tiefenebene %2 · %n Pixel</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ui::HistoryBridge</name>
    <message>
        <source>Paint Stroke</source>
        <translation>Pinselstrich</translation>
    </message>
    <message>
        <source>Fill</source>
        <translation>Füllen</translation>
    </message>
    <message>
        <source>Pop Up Region</source>
        <translation>Region hervorholen</translation>
    </message>
    <message>
        <source>Hide Regions</source>
        <translation>Regionen ausblenden</translation>
    </message>
    <message>
        <source>Unhide Regions</source>
        <translation>Regionen einblenden</translation>
    </message>
    <message>
        <source>Reset Region Order</source>
        <translation>Regionsreihenfolge zurücksetzen</translation>
    </message>
    <message>
        <source>Change Paint Target</source>
        <translation>Malziel wechseln</translation>
    </message>
    <message>
        <source>Run Script</source>
        <translation>Skript ausführen</translation>
    </message>
    <message>
        <source>Change Paint Layers</source>
        <translation>Malschichten ändern</translation>
    </message>
</context>
<context>
    <name>ui::HsvPicker</name>
    <message>
        <source>Saturation and value (square) and hue (bar)</source>
        <translation>Sättigung und Helligkeit (Quadrat) und Farbton (Leiste)</translation>
    </message>
</context>
<context>
    <name>ui::MainWindow</name>
    <message>
        <source>LayerPaint</source>
        <translation>LayerPaint</translation>
    </message>
    <message>
        <source>OpenGL Error</source>
        <translation>OpenGL-Fehler</translation>
    </message>
    <message>
        <source>The 3D view cannot be shown.</source>
        <translation>Die 3D-Ansicht kann nicht angezeigt werden.</translation>
    </message>
    <message>
        <source>Could not build the depth layers: %1</source>
        <translation>Die Tiefenebenen konnten nicht erstellt werden: %1</translation>
    </message>
    <message>
        <source>Trefoil knot</source>
        <translation>Kleeblattknoten</translation>
    </message>
    <message>
        <source>Hexagonal ring</source>
        <translation>Sechseckiger Ring</translation>
    </message>
    <message>
        <source>Row of four</source>
        <translation>Viererreihe</translation>
    </message>
    <message>
        <source>Torus knot (1M triangles)</source>
        <translation>Torusknoten (1 Mio. Dreiecke)</translation>
    </message>
    <message>
        <source>Torus knot (%1 triangles)</source>
        <translation>Torusknoten (%1 Dreiecke)</translation>
    </message>
    <message>
        <source>Segmentation</source>
        <translation>Segmentierung</translation>
    </message>
    <message>
        <source>Region Graph</source>
        <translation>Regionsgraph</translation>
    </message>
    <message>
        <source>&amp;Shaded</source>
        <translation>&amp;Schattiert</translation>
    </message>
    <message>
        <source>Show the model shaded, all depth layers</source>
        <translation>Das Modell schattiert zeigen, alle Tiefenebenen</translation>
    </message>
    <message>
        <source>Single Depth &amp;Layer</source>
        <translation>Einzelne Tiefen&amp;ebene</translation>
    </message>
    <message>
        <source>Se&amp;gmentation Map</source>
        <translation>Se&amp;gmentierungskarte</translation>
    </message>
    <message>
        <source>Colour every region of the visible depth layer differently</source>
        <translation>Jede Region der sichtbaren Tiefenebene anders einfärben</translation>
    </message>
    <message>
        <source>Region &amp;Boundaries</source>
        <translation>&amp;Regionsgrenzen</translation>
    </message>
    <message>
        <source>Outline where a surface is not connected to its neighbours on the same depth layer</source>
        <translation>Umrissen zeigen, wo eine Fläche nicht mit ihren Nachbarn auf derselben Tiefenebene verbunden ist</translation>
    </message>
    <message>
        <source>Building depth layers…</source>
        <translation>Tiefenebenen werden erstellt …</translation>
    </message>
    <message>
        <source>build_layers of this view:
capture %1 ms (drawing), %2 ms (sorting)
connectivity %3 ms, regions %4 ms
%5 ms from the capture to the picture</source>
        <translation>build_layers dieser Ansicht:
Erfassung %1 ms (Zeichnen), %2 ms (Sortieren)
Konnektivität %3 ms, Regionen %4 ms
%5 ms von der Erfassung bis zum Bild</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>Ö&amp;ffnen …</translation>
    </message>
    <message>
        <source>New from &amp;Built-in</source>
        <translation>Neu aus &amp;eingebautem Modell</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
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
        <source>&amp;Frame All</source>
        <translation>&amp;Alles einpassen</translation>
    </message>
    <message>
        <source>&amp;Orthographic</source>
        <translation>&amp;Orthografisch</translation>
    </message>
    <message>
        <source>&amp;Panels</source>
        <translation>&amp;Bedienfelder</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;About LayerPaint</source>
        <translation>Über &amp;LayerPaint</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>Über &amp;Qt</translation>
    </message>
    <message>
        <source>&amp;%1 %2</source>
        <translation>&amp;%1 %2</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>No Recent Files</source>
        <translation>Keine zuletzt geöffneten Dateien</translation>
    </message>
    <message>
        <source>&amp;Clear Menu</source>
        <translation>Liste &amp;leeren</translation>
    </message>
    <message>
        <source>glTF 2.0 (*.gltf *.glb)</source>
        <translation>glTF 2.0 (*.gltf *.glb)</translation>
    </message>
    <message>
        <source>Wavefront OBJ (*.obj)</source>
        <translation>Wavefront OBJ (*.obj)</translation>
    </message>
    <message>
        <source>Stanford PLY (*.ply)</source>
        <translation>Stanford PLY (*.ply)</translation>
    </message>
    <message>
        <source>STL (*.stl)</source>
        <translation>STL (*.stl)</translation>
    </message>
    <message>
        <source>Object File Format (*.off)</source>
        <translation>Object File Format (*.off)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Alle Dateien (*)</translation>
    </message>
    <message>
        <source>About LayerPaint</source>
        <translation>Über LayerPaint</translation>
    </message>
    <message>
        <source>&lt;h3&gt;LayerPaint %1&lt;/h3&gt;&lt;p&gt;Layer-aware 3D painting: paint surfaces hidden behind others in one stroke.&lt;/p&gt;&lt;p&gt;License: GNU GPL version 3 or later.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;LayerPaint %1&lt;/h3&gt;&lt;p&gt;Ebenenbewusstes 3D-Malen: Flächen, die hinter anderen verborgen liegen, in einem Strich bemalen.&lt;/p&gt;&lt;p&gt;Lizenz: GNU GPL Version 3 oder neuer.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Could not open %1</source>
        <translation>%1 konnte nicht geöffnet werden</translation>
    </message>
    <message>
        <source>Open Failed</source>
        <translation>Öffnen fehlgeschlagen</translation>
    </message>
    <message>
        <source>Could not open “%1”.</source>
        <translation>„%1“ konnte nicht geöffnet werden.</translation>
    </message>
    <message>
        <source>Opening %1 cancelled</source>
        <translation>Öffnen von %1 abgebrochen</translation>
    </message>
    <message>
        <source>Opening %1…</source>
        <translation>%1 wird geöffnet …</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Opening Model</source>
        <translation>Modell wird geöffnet</translation>
    </message>
    <message>
        <source>%1 — %2 vertices, %3 triangles</source>
        <translation>%1 – %2 Eckpunkte, %3 Dreiecke</translation>
    </message>
    <message>
        <source>&amp;Layer-Aware Painting</source>
        <translation>&amp;Ebenenbewusstes Malen</translation>
    </message>
    <message>
        <source>Layer-aware painting (L): strokes follow a surface behind whatever covers it</source>
        <translation>Ebenenbewusstes Malen (L): Striche folgen einer Fläche auch hinter dem, was sie verdeckt</translation>
    </message>
    <message>
        <source>Paint across depth layers; off: only the front-most surface is paintable</source>
        <translation>Über Tiefenebenen hinweg malen; aus: nur die vorderste Fläche ist bemalbar</translation>
    </message>
    <message>
        <source>Layer-aware painting</source>
        <translation>Ebenenbewusstes Malen</translation>
    </message>
    <message>
        <source>Conventional painting</source>
        <translation>Herkömmliches Malen</translation>
    </message>
    <message>
        <source>Show &amp;Brush Maps</source>
        <translation>Pinsel&amp;karten anzeigen</translation>
    </message>
    <message>
        <source>While painting, show the paintable (red) and trackable (blue) pixels around the brush</source>
        <translation>Beim Malen die bemalbaren (rot) und verfolgbaren (blau) Pixel um den Pinsel zeigen</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>&amp;Rückgängig: %1</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>&amp;Wiederherstellen: %1</translation>
    </message>
    <message>
        <source>Cannot paint this model: %1</source>
        <translation>Dieses Modell kann nicht bemalt werden: %1</translation>
    </message>
    <message>
        <source>Cannot paint: %1</source>
        <translation>Malen nicht möglich: %1</translation>
    </message>
    <message>
        <source>Cannot paint into that target: %1</source>
        <translation>In dieses Ziel kann nicht gemalt werden: %1</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>&amp;Paint</source>
        <translation>&amp;Malen</translation>
    </message>
    <message>
        <source>compute shader</source>
        <translation>Compute-Shader</translation>
    </message>
    <message>
        <source>C++</source>
        <translation>C++</translation>
    </message>
    <message>
        <source>Fill</source>
        <translation>Füllen</translation>
    </message>
    <message>
        <source>Tools</source>
        <translation>Werkzeuge</translation>
    </message>
    <message>
        <source>&amp;Brush</source>
        <translation>&amp;Pinsel</translation>
    </message>
    <message>
        <source>&amp;Eraser</source>
        <translation>&amp;Radierer</translation>
    </message>
    <message>
        <source>&amp;Fill</source>
        <translation>&amp;Füllen</translation>
    </message>
    <message>
        <source>Flood fill with the brush colour</source>
        <translation>Mit der Pinselfarbe flächig füllen</translation>
    </message>
    <message>
        <source>E&amp;yedropper</source>
        <translation>Pipe&amp;tte</translation>
    </message>
    <message>
        <source>Pick the surface colour under the cursor (or Ctrl+click)</source>
        <translation>Die Oberflächenfarbe unter dem Zeiger aufnehmen (oder Strg+Klick)</translation>
    </message>
    <message>
        <source>Paint to &amp;Hide</source>
        <translation>Durch Malen aus&amp;blenden</translation>
    </message>
    <message>
        <source>Hide every region the brush touches, revealing what lies behind</source>
        <translation>Jede Region ausblenden, die der Pinsel berührt, und freilegen, was dahinter liegt</translation>
    </message>
    <message>
        <source>&amp;Pop Up</source>
        <translation>&amp;Hervorholen</translation>
    </message>
    <message>
        <source>Cannot fill: %1</source>
        <translation>Füllen nicht möglich: %1</translation>
    </message>
    <message>
        <source>Filled in %1 ms</source>
        <translation>In %1 ms gefüllt</translation>
    </message>
    <message>
        <source>Nothing to fill there</source>
        <translation>Dort gibt es nichts zu füllen</translation>
    </message>
    <message>
        <source>Region %1 popped up</source>
        <translation>Region %1 hervorgeholt</translation>
    </message>
    <message>
        <source>Paint to Hide</source>
        <translation>Durch Malen ausblenden</translation>
    </message>
    <message>
        <source>Brush</source>
        <translation>Pinsel</translation>
    </message>
    <message>
        <source>Colour</source>
        <translation>Farbe</translation>
    </message>
    <message>
        <source>Layer-aware</source>
        <translation>Ebenenbewusst</translation>
    </message>
    <message>
        <source>S&amp;maller Brush</source>
        <translation>&amp;Kleinerer Pinsel</translation>
    </message>
    <message>
        <source>Make the brush smaller</source>
        <translation>Den Pinsel verkleinern</translation>
    </message>
    <message>
        <source>Make the brush larger</source>
        <translation>Den Pinsel vergrößern</translation>
    </message>
    <message>
        <source>Lower the brush hardness</source>
        <translation>Die Pinselhärte verringern</translation>
    </message>
    <message>
        <source>Har&amp;der Brush</source>
        <translation>Härterer Pin&amp;sel</translation>
    </message>
    <message>
        <source>Raise the brush hardness</source>
        <translation>Die Pinselhärte erhöhen</translation>
    </message>
    <message>
        <source>S&amp;wap Colours</source>
        <translation>Farben &amp;vertauschen</translation>
    </message>
    <message>
        <source>Swap the foreground and background colours (X)</source>
        <translation>Vorder- und Hintergrundfarbe tauschen (X)</translation>
    </message>
    <message>
        <source>Swap the foreground and background colours</source>
        <translation>Vorder- und Hintergrundfarbe tauschen</translation>
    </message>
    <message>
        <source>No surface here to pick a colour from</source>
        <translation>Hier ist keine Fläche, deren Farbe aufgenommen werden kann</translation>
    </message>
    <message>
        <source>Picked %1</source>
        <translation>%1 aufgenommen</translation>
    </message>
    <message>
        <source>Brush %1 px · %2 % hard</source>
        <translation>Pinsel %1 px · %2 % hart</translation>
    </message>
    <message>
        <source>Brush radius and hardness ([ ] and Shift+[ ] change them)</source>
        <translation>Pinselradius und -härte ([ ] und Umschalt+[ ] ändern sie)</translation>
    </message>
    <message>
        <source>&amp;Preferences…</source>
        <translation>&amp;Einstellungen…</translation>
    </message>
    <message>
        <source>Lar&amp;ger Brush</source>
        <translation>&amp;Größerer Pinsel</translation>
    </message>
    <message>
        <source>Sof&amp;ter Brush</source>
        <translation>&amp;Weicherer Pinsel</translation>
    </message>
    <message>
        <source>Projects and 3D models (*.glb *.gltf *.obj *.ply *.stl *.off)</source>
        <translation>Projekte und 3D-Modelle (*.glb *.gltf *.obj *.ply *.stl *.off)</translation>
    </message>
    <message>
        <source>LayerPaint projects (*.glb)</source>
        <translation>LayerPaint-Projekte (*.glb)</translation>
    </message>
    <message>
        <source>Open Project or Model</source>
        <translation>Projekt oder Modell öffnen</translation>
    </message>
    <message>
        <source>%1[*] — LayerPaint</source>
        <translation>%1[*] — LayerPaint</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <source>Save the painting and its settings as a project (.glb)</source>
        <translation>Die Bemalung und ihre Einstellungen als Projekt (.glb) speichern</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter …</translation>
    </message>
    <message>
        <source>Save the project under another name</source>
        <translation>Das Projekt unter einem anderen Namen speichern</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>E&amp;xportieren</translation>
    </message>
    <message>
        <source>glTF &amp;Binary (.glb)…</source>
        <translation>glTF &amp;binär (.glb) …</translation>
    </message>
    <message>
        <source>Wavefront &amp;OBJ (.obj + .mtl + textures)…</source>
        <translation>Wavefront &amp;OBJ (.obj + .mtl + Texturen) …</translation>
    </message>
    <message>
        <source>Stanford &amp;PLY with Vertex Colours…</source>
        <translation>Stanford &amp;PLY mit Vertexfarben …</translation>
    </message>
    <message>
        <source>Paint Texture as P&amp;NG (8-bit)…</source>
        <translation>Maltextur als P&amp;NG (8 Bit) …</translation>
    </message>
    <message>
        <source>Paint Texture as PNG (&amp;16-bit)…</source>
        <translation>Maltextur als PNG (&amp;16 Bit) …</translation>
    </message>
    <message>
        <source>Paint Texture as &amp;TIFF…</source>
        <translation>Maltextur als &amp;TIFF …</translation>
    </message>
    <message>
        <source>Paint Texture as Open&amp;EXR…</source>
        <translation>Maltextur als Open&amp;EXR …</translation>
    </message>
    <message>
        <source>Painting into a new target (Undo brings the previous one back)</source>
        <translation>Es wird in ein neues Malziel gemalt (Rückgängig holt das vorige zurück)</translation>
    </message>
    <message>
        <source>“%1” has no texture coordinates (UVs), so it is painted with vertex colours: the paint&apos;s detail follows its vertices.</source>
        <translation>„%1“ hat keine Texturkoordinaten (UVs) und wird daher mit Vertexfarben bemalt: Die Feinheit der Farbe folgt seinen Vertices.</translation>
    </message>
    <message>
        <source>Recovered the unsaved work on “%1” that was autosaved at %2. Save it to keep it.</source>
        <translation>Die ungesicherte Arbeit an „%1“, automatisch gesichert um %2, wurde wiederhergestellt. Speichern Sie sie, um sie zu behalten.</translation>
    </message>
    <message>
        <source>Opening “%1” gave these warnings:</source>
        <translation>Beim Öffnen von „%1“ gab es diese Warnungen:</translation>
    </message>
    <message>
        <source>Warnings while loading are shown above the view</source>
        <translation>Warnungen beim Laden stehen oben in der Ansicht</translation>
    </message>
    <message>
        <source>“%1” has no texture coordinates (UVs). Its vertices are far apart for the brush, so it gets an automatic UV layout to paint into a texture.</source>
        <translation>„%1“ hat keine Texturkoordinaten (UVs). Seine Vertices liegen für den Pinsel weit auseinander, daher bekommt es ein automatisches UV-Layout, um in eine Textur zu malen.</translation>
    </message>
    <message>
        <source>Making an automatic UV layout…</source>
        <translation>Automatisches UV-Layout wird erstellt …</translation>
    </message>
    <message>
        <source>The automatic UV layout was cancelled; the paint target stays as it was</source>
        <translation>Das automatische UV-Layout wurde abgebrochen; das Malziel bleibt, wie es war</translation>
    </message>
    <message>
        <source>Cannot paint into a texture with an automatic UV layout: %1</source>
        <translation>Malen in eine Textur mit automatischem UV-Layout nicht möglich: %1</translation>
    </message>
    <message>
        <source>Painting into a texture with an automatic UV layout (Undo brings the previous target back)</source>
        <translation>Es wird in eine Textur mit automatischem UV-Layout gemalt (Rückgängig holt das vorige Ziel zurück)</translation>
    </message>
    <message>
        <source>Painting into a texture with an automatic UV layout</source>
        <translation>Es wird in eine Textur mit automatischem UV-Layout gemalt</translation>
    </message>
    <message>
        <source>Use Vertex Colours Instead</source>
        <translation>Stattdessen Vertexfarben verwenden</translation>
    </message>
    <message>
        <source>Paint into a Texture (Automatic UV Layout)</source>
        <translation>In eine Textur malen (automatisches UV-Layout)</translation>
    </message>
    <message>
        <source>Depth Layers</source>
        <translation>Tiefenebenen</translation>
    </message>
    <message>
        <source>Show one depth layer alone (choose it in the Depth Layers panel)</source>
        <translation>Eine Tiefenebene allein zeigen (im Bedienfeld Tiefenebenen wählen)</translation>
    </message>
    <message>
        <source>Depth layers: %1 · Fragments: %2 · Regions: %3 · Built in %4 ms</source>
        <translation>Tiefenebenen: %1 · Fragmente: %2 · Regionen: %3 · Erstellt in %4 ms</translation>
    </message>
    <message>
        <source>Paint Layers</source>
        <translation>Malschichten</translation>
    </message>
    <message>
        <source>Paint &amp;Layers</source>
        <translation>Mal&amp;schichten</translation>
    </message>
    <message>
        <source>Vertex colours hold base colour only: roughness and metallic need a texture as the paint target.</source>
        <translation>Vertexfarben tragen nur die Grundfarbe: Rauheit und Metallisch brauchen eine Textur als Malziel.</translation>
    </message>
    <message>
        <source>Paint strokes with the brush; Shift+click draws a straight line on from the last stroke</source>
        <translation>Mit dem Pinsel Striche malen; Umschalt+Klick zieht eine gerade Linie vom Ende des letzten Strichs</translation>
    </message>
    <message>
        <source>Erase paint back to the model&apos;s original colours; Shift+click erases along a straight line from the last stroke</source>
        <translation>Farbe bis auf die ursprünglichen Farben des Modells wegradieren; Umschalt+Klick radiert entlang einer geraden Linie vom letzten Strich</translation>
    </message>
    <message>
        <source>Bring the region below the visible one to the front (or Ctrl+Shift+click); click again to cycle</source>
        <translation>Die Region unter der sichtbaren nach vorn holen (oder Strg+Umschalt+Klick); erneut klicken, um durchzuschalten</translation>
    </message>
    <message>
        <source>Straight line from the end of the last stroke</source>
        <translation>Gerade Linie vom Ende des letzten Strichs</translation>
    </message>
    <message>
        <source>No stroke to go on from: a dot here; the next Shift+click draws a line from it</source>
        <translation>Kein Strich zum Fortsetzen: hier ein Punkt; der nächste Umschalt+Klick zieht eine Linie von ihm aus</translation>
    </message>
    <message>
        <source>Stroke Stabili&amp;zer</source>
        <translation>Strich-Stabi&amp;lisator</translation>
    </message>
    <message>
        <source>Strokes follow the pointer on a string, smoothing out wobbles (length and smoothing in the Brush panel)</source>
        <translation>Striche folgen dem Zeiger an einer Schnur und glätten Zittern (Länge und Glättung im Pinsel-Bedienfeld)</translation>
    </message>
    <message>
        <source>&amp;Channel</source>
        <translation>Ka&amp;nal</translation>
    </message>
    <message>
        <source>&amp;Material</source>
        <translation>&amp;Material</translation>
    </message>
    <message>
        <source>Show the paint lit as a metallic-roughness material</source>
        <translation>Die Farbe als beleuchtetes Metallic-Roughness-Material zeigen</translation>
    </message>
    <message>
        <source>&amp;Base Colour</source>
        <translation>&amp;Grundfarbe</translation>
    </message>
    <message>
        <source>Show the base colour alone, unlit</source>
        <translation>Nur die Grundfarbe zeigen, unbeleuchtet</translation>
    </message>
    <message>
        <source>&amp;Roughness</source>
        <translation>&amp;Rauheit</translation>
    </message>
    <message>
        <source>Show roughness as grey: black smooth, white rough</source>
        <translation>Rauheit als Grau zeigen: schwarz glatt, weiß rau</translation>
    </message>
    <message>
        <source>M&amp;etallic</source>
        <translation>M&amp;etallisch</translation>
    </message>
    <message>
        <source>Show metallic as grey: black non-metal, white metal</source>
        <translation>Metallisch als Grau zeigen: schwarz Nichtmetall, weiß Metall</translation>
    </message>
    <message>
        <source>Brush Presets</source>
        <translation>Pinselvorgaben</translation>
    </message>
    <message>
        <source>Brush preset: %1</source>
        <translation>Pinselvorgabe: %1</translation>
    </message>
    <message>
        <source>One page on layer-aware painting, pop-up, paint to hide, orbiting and the keys</source>
        <translation>Eine Seite über ebenenbewusstes Malen, Hervorholen, Ausblenden durch Malen, Drehen und die Tasten</translation>
    </message>
    <message>
        <source>Quick &amp;Guide</source>
        <translation>Kurz&amp;anleitung</translation>
    </message>
    <message>
        <source>Building the symmetric views… %1 %</source>
        <translation>Die symmetrischen Ansichten werden erstellt… %1 %</translation>
    </message>
    <message>
        <source>Waiting for the symmetric views before painting…</source>
        <translation>Vor dem Malen wird auf die symmetrischen Ansichten gewartet…</translation>
    </message>
    <message>
        <source>The symmetric views could not be built: this stroke paints without its copies</source>
        <translation>Die symmetrischen Ansichten konnten nicht erstellt werden: dieser Strich malt ohne seine Kopien</translation>
    </message>
    <message>
        <source>S&amp;ymmetry</source>
        <translation>S&amp;ymmetrie</translation>
    </message>
    <message>
        <source>Mirror &amp;X</source>
        <translation>&amp;X spiegeln</translation>
    </message>
    <message>
        <source>Mirror &amp;Y</source>
        <translation>&amp;Y spiegeln</translation>
    </message>
    <message>
        <source>Mirror &amp;Z</source>
        <translation>&amp;Z spiegeln</translation>
    </message>
    <message>
        <source>Repeat every dab mirrored across the model&apos;s plane across this axis, also where that side is hidden or faces away</source>
        <translation>Jeden Tupfer an der Ebene des Modells quer zu dieser Achse gespiegelt wiederholen, auch wo diese Seite verdeckt oder abgewandt ist</translation>
    </message>
    <message>
        <source>Symmetry &amp;Off</source>
        <translation>Symmetrie &amp;aus</translation>
    </message>
    <message>
        <source>No mirrored or radial copies of the dabs</source>
        <translation>Keine gespiegelten oder radialen Kopien der Tupfer</translation>
    </message>
    <message>
        <source>Symmetry &amp;Settings…</source>
        <translation>Symmetrie-&amp;Einstellungen…</translation>
    </message>
    <message>
        <source>Show the Brush panel&apos;s symmetry settings: the centre and radial copies</source>
        <translation>Die Symmetrie-Einstellungen des Pinsel-Bedienfelds zeigen: Mittelpunkt und radiale Kopien</translation>
    </message>
    <message>
        <source>Symmetry: every dab repeated on the mirrored surface, also where it is hidden (radial copies in the Brush panel)</source>
        <translation>Symmetrie: jeder Tupfer auf der gespiegelten Oberfläche wiederholt, auch wo sie verdeckt ist (radiale Kopien im Pinsel-Bedienfeld)</translation>
    </message>
    <message>
        <source>%1× radial</source>
        <translation>%1× radial</translation>
    </message>
    <message>
        <source>Symmetry: off</source>
        <translation>Symmetrie: aus</translation>
    </message>
    <message>
        <source>Symmetry: %1</source>
        <translation>Symmetrie: %1</translation>
    </message>
    <message>
        <source>&amp;Raise Texture Size…</source>
        <translation>Texturgröße &amp;erhöhen…</translation>
    </message>
    <message>
        <source>A texture&apos;s size can be raised while painting into a texture (Paint into, on the brush bar)</source>
        <translation>Die Größe einer Textur lässt sich erhöhen, während in eine Textur gemalt wird („Malen in“ in der Pinselleiste)</translation>
    </message>
    <message>
        <source>material %1</source>
        <translation>Material %1</translation>
    </message>
    <message>
        <source>%1. %2 (%3 × %4)</source>
        <translation>%1. %2 (%3 × %4)</translation>
    </message>
    <message>
        <source>Raise Texture Size</source>
        <translation>Texturgröße erhöhen</translation>
    </message>
    <message>
        <source>The material whose texture gets larger:</source>
        <translation>Das Material, dessen Textur größer wird:</translation>
    </message>
    <message>
        <source>%1 × %2</source>
        <translation>%1 × %2</translation>
    </message>
    <message>
        <source>That texture is as large as a texture can be (8192 texels on a side)</source>
        <translation>Diese Textur ist schon so groß, wie eine Textur sein kann (8192 Texel je Seite)</translation>
    </message>
    <message>
        <source>New size (now %1 × %2; what is painted is resampled):</source>
        <translation>Neue Größe (jetzt %1 × %2; Bemaltes wird neu abgetastet):</translation>
    </message>
    <message>
        <source>Cannot raise the texture size: %1</source>
        <translation>Die Texturgröße lässt sich nicht erhöhen: %1</translation>
    </message>
    <message>
        <source>The texture is %1 now (Undo brings the previous size back)</source>
        <translation>Die Textur ist jetzt %1 (Rückgängig stellt die vorige Größe wieder her)</translation>
    </message>
    <message>
        <source>A Fill Layer Takes No Strokes</source>
        <translation>Eine Füllschicht nimmt keine Striche an</translation>
    </message>
    <message>
        <source>“%1” is a fill layer: its values are the same everywhere. Paint its mask to shape where it shows, or paint on a paint layer above it.</source>
        <translation>„%1“ ist eine Füllschicht: Ihre Werte sind überall gleich. Malen Sie ihre Maske, um zu formen, wo sie sichtbar ist, oder malen Sie auf einer Malschicht darüber.</translation>
    </message>
    <message>
        <source>Paint Its Mask</source>
        <translation>Ihre Maske malen</translation>
    </message>
    <message>
        <source>Add a Mask and Paint It</source>
        <translation>Maske hinzufügen und malen</translation>
    </message>
    <message>
        <source>Add a Paint Layer Above</source>
        <translation>Malschicht darüber hinzufügen</translation>
    </message>
    <message>
        <source>Painting the mask of “%1”</source>
        <translation>Male in die Maske von „%1“</translation>
    </message>
    <message>
        <source>Painting “%1”</source>
        <translation>Male in „%1“</translation>
    </message>
    <message>
        <source>Strokes paint the mask: black hides the paint layer, white shows it</source>
        <translation>Striche malen die Maske: Schwarz verbirgt die Malschicht, Weiß zeigt sie</translation>
    </message>
    <message>
        <source>Strokes paint this paint layer</source>
        <translation>Striche malen in diese Malschicht</translation>
    </message>
    <message>
        <source>Export &amp;Textures…</source>
        <translation>&amp;Texturen exportieren…</translation>
    </message>
    <message>
        <source>Write each texture set&apos;s maps for a game engine or another tool, through an export preset</source>
        <translation>Die Maps jedes Texturensatzes für eine Spiel-Engine oder ein anderes Programm schreiben, über eine Exportvorgabe</translation>
    </message>
    <message>
        <source>The mask alone: black hides, white shows. Alt+click it again to see the paint layers.</source>
        <translation>Die Maske allein: Schwarz verbirgt, Weiß zeigt. Erneut Alt+Klick darauf, um die Malschichten wieder zu sehen.</translation>
    </message>
    <message>
        <source>The paint layers again</source>
        <translation>Wieder die Malschichten</translation>
    </message>
</context>
<context>
    <name>ui::MessageBar</name>
    <message>
        <source>Dismiss</source>
        <translation>Schließen</translation>
    </message>
    <message numerus="yes">
        <source>… and %n more (see the tooltip)</source>
        <translation>
            <numerusform>… und %n weitere (siehe Tooltip)</numerusform>
            <numerusform>… und %n weitere (siehe Tooltip)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ui::PaintLayersPanel</name>
    <message>
        <source>Normal</source>
        <translation>Normal</translation>
    </message>
    <message>
        <source>Multiply</source>
        <translation>Multiplizieren</translation>
    </message>
    <message>
        <source>Screen</source>
        <translation>Negativ multiplizieren</translation>
    </message>
    <message>
        <source>Overlay</source>
        <translation>Ineinanderkopieren</translation>
    </message>
    <message>
        <source>Soft Light</source>
        <translation>Weiches Licht</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Addieren</translation>
    </message>
    <message>
        <source>Subtract</source>
        <translation>Subtrahieren</translation>
    </message>
    <message>
        <source>Darken</source>
        <translation>Abdunkeln</translation>
    </message>
    <message>
        <source>Lighten</source>
        <translation>Aufhellen</translation>
    </message>
    <message>
        <source>Difference</source>
        <translation>Differenz</translation>
    </message>
    <message>
        <source>The paint layers, the uppermost on top. Click a row to paint on it, its eye to show or hide it, its mask to paint the mask; double-click a name to rename it; drag rows to reorder them.</source>
        <translation>Die Malschichten, die oberste oben. Klicken Sie auf eine Zeile, um darauf zu malen, auf ihr Auge, um sie zu zeigen oder auszublenden, auf ihre Maske, um die Maske zu malen; Doppelklick auf einen Namen benennt um; Zeilen ziehen ordnet sie um.</translation>
    </message>
    <message>
        <source>How much of the current paint layer shows</source>
        <translation>Wie viel von der aktuellen Malschicht sichtbar ist</translation>
    </message>
    <message>
        <source>&amp;Opacity</source>
        <translation>&amp;Deckkraft</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>How the current paint layer combines with what lies under it</source>
        <translation>Wie sich die aktuelle Malschicht mit dem darunter Liegenden verbindet</translation>
    </message>
    <message>
        <source>&amp;Blend mode</source>
        <translation>&amp;Mischmodus</translation>
    </message>
    <message>
        <source>Lock &amp;transparency</source>
        <translation>&amp;Transparenz sperren</translation>
    </message>
    <message>
        <source>Painting changes the colour of what is on the paint layer, never where it is or how much</source>
        <translation>Malen ändert die Farbe dessen, was auf der Malschicht ist, nie wo es ist oder wie viel</translation>
    </message>
    <message>
        <source>&amp;New Paint Layer</source>
        <translation>&amp;Neue Malschicht</translation>
    </message>
    <message>
        <source>New</source>
        <translation>Neu</translation>
    </message>
    <message>
        <source>Add a paint layer above the current one</source>
        <translation>Eine Malschicht über der aktuellen hinzufügen</translation>
    </message>
    <message>
        <source>New F&amp;ill Layer</source>
        <translation>Neue &amp;Füllschicht</translation>
    </message>
    <message>
        <source>Fill</source>
        <translation>Füllen</translation>
    </message>
    <message>
        <source>Add a paint layer of uniform channel values (the brush&apos;s) above the current one</source>
        <translation>Eine Malschicht mit einheitlichen Kanalwerten (denen des Pinsels) über der aktuellen hinzufügen</translation>
    </message>
    <message>
        <source>&amp;Duplicate Paint Layer</source>
        <translation>Malschicht &amp;duplizieren</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Duplizieren</translation>
    </message>
    <message>
        <source>Copy the current paint layer</source>
        <translation>Die aktuelle Malschicht kopieren</translation>
    </message>
    <message>
        <source>D&amp;elete Paint Layer</source>
        <translation>Malschicht &amp;löschen</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <source>Delete the current paint layer</source>
        <translation>Die aktuelle Malschicht löschen</translation>
    </message>
    <message>
        <source>&amp;Merge Down</source>
        <translation>Nach unten &amp;zusammenführen</translation>
    </message>
    <message>
        <source>Merge</source>
        <translation>Zusammenführen</translation>
    </message>
    <message>
        <source>Merge the current paint layer into the one below</source>
        <translation>Die aktuelle Malschicht mit der darunter zusammenführen</translation>
    </message>
    <message>
        <source>&amp;Flatten Paint Layers</source>
        <translation>Malschichten &amp;reduzieren</translation>
    </message>
    <message>
        <source>Flatten</source>
        <translation>Reduzieren</translation>
    </message>
    <message>
        <source>Merge every visible paint layer into one</source>
        <translation>Alle sichtbaren Malschichten zu einer zusammenführen</translation>
    </message>
    <message>
        <source>Flattened</source>
        <translation>Reduziert</translation>
    </message>
    <message>
        <source>Add M&amp;ask</source>
        <translation>&amp;Maske hinzufügen</translation>
    </message>
    <message>
        <source>Mask</source>
        <translation>Maske</translation>
    </message>
    <message>
        <source>Give the current paint layer a mask (black hides, white shows)</source>
        <translation>Der aktuellen Malschicht eine Maske geben (Schwarz verbirgt, Weiß zeigt)</translation>
    </message>
    <message>
        <source>Delete Mas&amp;k</source>
        <translation>Maske &amp;entfernen</translation>
    </message>
    <message>
        <source>No Mask</source>
        <translation>Keine Maske</translation>
    </message>
    <message>
        <source>Remove the current paint layer&apos;s mask</source>
        <translation>Die Maske der aktuellen Malschicht entfernen</translation>
    </message>
    <message>
        <source>&amp;Rename…</source>
        <translation>&amp;Umbenennen…</translation>
    </message>
    <message>
        <source>Open a model to paint in paint layers.</source>
        <translation>Öffnen Sie ein Modell, um in Malschichten zu malen.</translation>
    </message>
    <message>
        <source>Vertex colours have no paint layers: choose a texture as the paint target (in the brush bar) to paint in paint layers.</source>
        <translation>Vertexfarben haben keine Malschichten: Wählen Sie eine Textur als Malziel (in der Pinselleiste), um in Malschichten zu malen.</translation>
    </message>
    <message>
        <source>Shown: click to hide</source>
        <translation>Sichtbar: Klicken zum Ausblenden</translation>
    </message>
    <message>
        <source>Hidden: click to show</source>
        <translation>Ausgeblendet: Klicken zum Zeigen</translation>
    </message>
    <message>
        <source>fill layer</source>
        <translation>Füllschicht</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>, </source>
        <translation>, </translation>
    </message>
    <message>
        <source>Base</source>
        <translation>Basis</translation>
    </message>
    <message>
        <source>The model&apos;s own surface (painting here changes it directly)</source>
        <translation>Die eigene Oberfläche des Modells (Malen hier ändert sie direkt)</translation>
    </message>
    <message>
        <source>Paint layers: %1</source>
        <translation>Malschichten: %1</translation>
    </message>
    <message>
        <source>Fill %1</source>
        <translation>Füllung %1</translation>
    </message>
    <message>
        <source>Paint Layer %1</source>
        <translation>Malschicht %1</translation>
    </message>
    <message>
        <source>Whether the fill layer sets the base colour</source>
        <translation>Ob die Füllschicht die Grundfarbe setzt</translation>
    </message>
    <message>
        <source>The fill layer&apos;s base colour (click to choose)</source>
        <translation>Die Grundfarbe der Füllschicht (klicken zum Auswählen)</translation>
    </message>
    <message>
        <source>&amp;Fill colour</source>
        <translation>&amp;Füllfarbe</translation>
    </message>
    <message>
        <source>Fill Layer Colour</source>
        <translation>Farbe der Füllschicht</translation>
    </message>
    <message>
        <source>&amp;Roughness</source>
        <translation>&amp;Rauheit</translation>
    </message>
    <message>
        <source>The roughness the fill layer sets; Off leaves roughness alone</source>
        <translation>Die Rauheit, die die Füllschicht setzt; Aus lässt die Rauheit unverändert</translation>
    </message>
    <message>
        <source>&amp;Metallic</source>
        <translation>Meta&amp;llisch</translation>
    </message>
    <message>
        <source>How metallic the fill layer makes the surface; Off leaves metallic alone</source>
        <translation>Wie metallisch die Füllschicht die Oberfläche macht; Aus lässt Metallisch unverändert</translation>
    </message>
    <message>
        <source>Texture set:</source>
        <translation>Texturset:</translation>
    </message>
    <message>
        <source>Each texture the model paints into, with the materials on it, is a texture set. The thumbnails show the chosen one&apos;s paint; strokes paint every texture set they cross.</source>
        <translation>Jede Textur, in die das Modell malt, bildet mit ihren Materialien ein Texturset. Die Vorschaubilder zeigen die Farbe des gewählten; Striche bemalen jedes Texturset, das sie kreuzen.</translation>
    </message>
    <message>
        <source>Texture set %1</source>
        <translation>Texturset %1</translation>
    </message>
    <message>
        <source>%1 (%2 × %3)</source>
        <translation>%1 (%2 × %3)</translation>
    </message>
    <message>
        <source>Shown alone in the view: Alt+click to see the paint layers again</source>
        <translation>Allein in der Ansicht gezeigt: Alt+Klick, um die Malschichten wieder zu sehen</translation>
    </message>
    <message>
        <source>Painting the mask (black hides, white shows); Alt+click shows it alone</source>
        <translation>Die Maske wird bemalt (Schwarz verbirgt, Weiß zeigt); Alt+Klick zeigt sie allein</translation>
    </message>
    <message>
        <source>Mask: click to paint it, Alt+click to see it alone</source>
        <translation>Maske: Klick zum Bemalen, Alt+Klick, um sie allein zu sehen</translation>
    </message>
</context>
<context>
    <name>ui::PaintTargetJob</name>
    <message>
        <source>Making an automatic UV layout for “%1”…</source>
        <translation>Automatisches UV-Layout für „%1“ wird erstellt …</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Automatic UV Layout</source>
        <translation>Automatisches UV-Layout</translation>
    </message>
</context>
<context>
    <name>ui::PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source> MiB</source>
        <translation> MiB</translation>
    </message>
    <message>
        <source>The most memory undo keeps; the oldest strokes are forgotten beyond it</source>
        <translation>Wie viel Speicher das Rückgängigmachen höchstens belegt; darüber hinaus werden die ältesten Striche vergessen</translation>
    </message>
    <message>
        <source>&amp;Undo memory:</source>
        <translation>Speicher für &amp;Rückgängig:</translation>
    </message>
    <message>
        <source>%1 × %1</source>
        <translation>%1 × %1</translation>
    </message>
    <message>
        <source>The size of a new texture for models without one to paint (used from the next model on)</source>
        <translation>Die Größe einer neuen Textur für Modelle ohne bemalbare Textur (ab dem nächsten Modell)</translation>
    </message>
    <message>
        <source>New &amp;texture size:</source>
        <translation>Größe neuer &amp;Texturen:</translation>
    </message>
    <message>
        <source>Pen pressure curve (pressure to the power of this): below 1 a light touch gives more, above 1 it takes a firm press</source>
        <translation>Stiftdruckkurve (Druck hoch diesem Wert): unter 1 bewirkt leichtes Aufsetzen mehr, über 1 braucht es festen Druck</translation>
    </message>
    <message>
        <source>&amp;Pressure curve:</source>
        <translation>&amp;Druckkurve:</translation>
    </message>
    <message>
        <source>Both: the middle button and Alt with any button</source>
        <translation>Beide: mittlere Taste und Alt mit jeder Taste</translation>
    </message>
    <message>
        <source>Blender-like: middle drag orbits, Shift+middle pans</source>
        <translation>Wie Blender: Ziehen mit der mittleren Taste dreht, Umschalt+Mitte verschiebt</translation>
    </message>
    <message>
        <source>Alt-based: Alt+left orbits, Alt+middle pans, Alt+right zooms</source>
        <translation>Mit Alt: Alt+links dreht, Alt+Mitte verschiebt, Alt+rechts zoomt</translation>
    </message>
    <message>
        <source>Which buttons move the camera; the wheel always zooms</source>
        <translation>Welche Tasten die Kamera bewegen; das Mausrad zoomt immer</translation>
    </message>
    <message>
        <source>&amp;Camera buttons:</source>
        <translation>&amp;Kameratasten:</translation>
    </message>
    <message>
        <source>System</source>
        <translation>System</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>&amp;Sprache:</translation>
    </message>
    <message>
        <source>A new language applies after a restart.</source>
        <translation>Eine neue Sprache gilt nach einem Neustart.</translation>
    </message>
    <message>
        <source> min</source>
        <translation> min</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <source>How often a recovery copy of the work is saved; 0 turns it off</source>
        <translation>Wie oft eine Wiederherstellungskopie der Arbeit gespeichert wird; 0 schaltet es aus</translation>
    </message>
    <message>
        <source>&amp;Autosave every:</source>
        <translation>&amp;Automatisch speichern alle:</translation>
    </message>
</context>
<context>
    <name>ui::PressureCurveView</name>
    <message>
        <source>Pen pressure (right) to stroke pressure (up)</source>
        <translation>Stiftdruck (rechts) zu Strichdruck (oben)</translation>
    </message>
</context>
<context>
    <name>ui::ProjectController</name>
    <message>
        <source>Autosaved</source>
        <translation>Automatisch gesichert</translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Automatisches Sichern fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>There is no model to save.</source>
        <translation>Es gibt kein Modell zum Speichern.</translation>
    </message>
    <message>
        <source>Save Project</source>
        <translation>Projekt speichern</translation>
    </message>
    <message>
        <source>LayerPaint projects (*.glb)</source>
        <translation>LayerPaint-Projekte (*.glb)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Still busy with the last save or export</source>
        <translation>Noch mit dem letzten Speichern oder Export beschäftigt</translation>
    </message>
    <message>
        <source>Save Failed</source>
        <translation>Speichern fehlgeschlagen</translation>
    </message>
    <message>
        <source>Could not save.</source>
        <translation>Konnte nicht speichern.</translation>
    </message>
    <message>
        <source>Saving %1…</source>
        <translation>%1 wird gespeichert …</translation>
    </message>
    <message>
        <source>Saving cancelled; the file was not changed</source>
        <translation>Speichern abgebrochen; die Datei wurde nicht verändert</translation>
    </message>
    <message>
        <source>Could not save %1</source>
        <translation>%1 konnte nicht gespeichert werden</translation>
    </message>
    <message>
        <source>Could not save “%1”. The file on disk was not changed.</source>
        <translation>„%1“ konnte nicht gespeichert werden. Die Datei auf dem Datenträger wurde nicht verändert.</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <source>“%1” has unsaved changes.</source>
        <translation>„%1“ hat ungespeicherte Änderungen.</translation>
    </message>
    <message>
        <source>Do you want to save them?</source>
        <translation>Möchten Sie sie speichern?</translation>
    </message>
    <message>
        <source>glTF binary (*.glb)</source>
        <translation>glTF binär (*.glb)</translation>
    </message>
    <message>
        <source>Wavefront OBJ (*.obj)</source>
        <translation>Wavefront OBJ (*.obj)</translation>
    </message>
    <message>
        <source>Stanford PLY (*.ply)</source>
        <translation>Stanford PLY (*.ply)</translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation>PNG-Bild (*.png)</translation>
    </message>
    <message>
        <source>TIFF image (*.tif *.tiff)</source>
        <translation>TIFF-Bild (*.tif *.tiff)</translation>
    </message>
    <message>
        <source>OpenEXR image (*.exr)</source>
        <translation>OpenEXR-Bild (*.exr)</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <source>The model is painted with vertex colours, so there is no paint texture: export it as glTF or PLY.</source>
        <translation>Das Modell ist mit Vertexfarben bemalt, es gibt also keine Maltextur: exportieren Sie es als glTF oder PLY.</translation>
    </message>
    <message>
        <source>Export Failed</source>
        <translation>Export fehlgeschlagen</translation>
    </message>
    <message>
        <source>Could not export the paint texture.</source>
        <translation>Die Maltextur konnte nicht exportiert werden.</translation>
    </message>
    <message>
        <source>Exporting %1…</source>
        <translation>%1 wird exportiert …</translation>
    </message>
    <message>
        <source>Export cancelled</source>
        <translation>Export abgebrochen</translation>
    </message>
    <message>
        <source>Could not export “%1”.</source>
        <translation>„%1“ konnte nicht exportiert werden.</translation>
    </message>
    <message numerus="yes">
        <source>Exported %n file(s) to %1</source>
        <translation>
            <numerusform>%n Datei nach %1 exportiert</numerusform>
            <numerusform>%n Dateien nach %1 exportiert</numerusform>
        </translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>LayerPaint</source>
        <translation>LayerPaint</translation>
    </message>
    <message>
        <source>an unsaved painting of %1</source>
        <translation>einer ungespeicherten Bemalung von %1</translation>
    </message>
    <message>
        <source>Recover Unsaved Work</source>
        <translation>Ungespeicherte Arbeit wiederherstellen</translation>
    </message>
    <message>
        <source>LayerPaint was not closed properly. Work on %1 was autosaved at %2.</source>
        <translation>LayerPaint wurde nicht ordnungsgemäß beendet. Die Arbeit an %1 wurde um %2 automatisch gesichert.</translation>
    </message>
    <message>
        <source>Recover it? It opens as an unsaved document.</source>
        <translation>Wiederherstellen? Sie öffnet sich als ungespeichertes Dokument.</translation>
    </message>
    <message>
        <source>&amp;Recover</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <source>&amp;Discard</source>
        <translation>&amp;Verwerfen</translation>
    </message>
    <message>
        <source>&amp;Not Now</source>
        <translation>&amp;Nicht jetzt</translation>
    </message>
    <message>
        <source>“%1” is the open project. Exporting there would replace it with a plain model without its LayerPaint settings. Choose another name, or use File ▸ Save.</source>
        <translation>„%1“ ist das geöffnete Projekt. Ein Export dorthin würde es durch ein einfaches Modell ohne seine LayerPaint-Einstellungen ersetzen. Wählen Sie einen anderen Namen oder verwenden Sie Datei ▸ Speichern.</translation>
    </message>
    <message>
        <source>Not exported: “%1” is the open project</source>
        <translation>Nicht exportiert: „%1“ ist das geöffnete Projekt</translation>
    </message>
    <message>
        <source>Export Refused</source>
        <translation>Export abgelehnt</translation>
    </message>
    <message>
        <source>Could not export to “%1”.</source>
        <translation>Export nach „%1“ nicht möglich.</translation>
    </message>
    <message>
        <source>Also write each &amp;paint layer as images</source>
        <translation>Auch jede &amp;Malschicht als Bilder schreiben</translation>
    </message>
    <message>
        <source>Beside the export, per paint layer: NAME_layer-N-LAYER_basecolor.png and its roughness, metallic and mask images, as the command line&apos;s --per-layer</source>
        <translation>Neben dem Export, je Malschicht: NAME_layer-N-SCHICHT_basecolor.png und ihre Bilder für Rauheit, Metall und Maske, wie --per-layer der Kommandozeile</translation>
    </message>
    <message>
        <source>The model has no paint layers</source>
        <translation>Das Modell hat keine Malschichten</translation>
    </message>
    <message>
        <source>There are no paint layers to export (they need a paint texture).</source>
        <translation>Es gibt keine Malschichten zum Exportieren (sie brauchen eine Maltextur).</translation>
    </message>
    <message>
        <source>Could not export the paint layers.</source>
        <translation>Die Malschichten konnten nicht exportiert werden.</translation>
    </message>
    <message>
        <source>Not Everything Was Kept</source>
        <translation>Nicht alles wurde behalten</translation>
    </message>
    <message>
        <source>“%1” was written, but not all of the model could be kept:</source>
        <translation>„%1“ wurde geschrieben, aber nicht alles am Modell konnte behalten werden:</translation>
    </message>
    <message>
        <source>Exporting textures to %1…</source>
        <translation>Texturen werden nach %1 exportiert…</translation>
    </message>
</context>
<context>
    <name>ui::QuickGuideDialog</name>
    <message>
        <source>Quick Guide</source>
        <translation>Kurzanleitung</translation>
    </message>
    <message>
        <source>&lt;h2&gt;LayerPaint in one page&lt;/h2&gt;&lt;p&gt;LayerPaint splits the view into &lt;b&gt;depth layers&lt;/b&gt; (the first, second, … surface under each pixel) and regions, so you can paint surfaces that others hide. Turn &lt;i&gt;Layer-aware&lt;/i&gt; on with &lt;b&gt;L&lt;/b&gt; or the check box in the tool bar.&lt;/p&gt;</source>
        <translation>&lt;h2&gt;LayerPaint auf einer Seite&lt;/h2&gt;&lt;p&gt;LayerPaint teilt die Ansicht in &lt;b&gt;Tiefenebenen&lt;/b&gt; (die erste, zweite, … Oberfläche unter jedem Pixel) und Regionen, sodass Sie Oberflächen bemalen können, die andere verdecken. Schalten Sie &lt;i&gt;Ebenenbewusst&lt;/i&gt; mit &lt;b&gt;L&lt;/b&gt; oder dem Kontrollkästchen in der Werkzeugleiste ein.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Layer-aware stroke&lt;/h3&gt;&lt;p&gt;Drag with the brush (&lt;b&gt;B&lt;/b&gt;). With layer-aware painting on, the stroke stays on the surface it started on, also where it goes behind another one. Shift+click draws a straight line on from the end of the last stroke.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Ebenenbewusster Strich&lt;/h3&gt;&lt;p&gt;Ziehen Sie mit dem Pinsel (&lt;b&gt;B&lt;/b&gt;). Mit ebenenbewusstem Malen bleibt der Strich auf der Oberfläche, auf der er begann, auch wo er hinter eine andere geht. Umschalt+Klick zieht eine gerade Linie vom Ende des letzten Strichs.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Pop-up&lt;/h3&gt;&lt;p&gt;&lt;b&gt;Ctrl+Shift+click&lt;/b&gt; with any tool, or a click with the Pop Up tool (&lt;b&gt;P&lt;/b&gt;), brings the region under the visible one to the front. Click the same spot again to go deeper; after the last it starts from the top. &lt;b&gt;R&lt;/b&gt; resets the order.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Hervorholen&lt;/h3&gt;&lt;p&gt;&lt;b&gt;Strg+Umschalt+Klick&lt;/b&gt; mit jedem Werkzeug oder ein Klick mit dem Werkzeug Hervorholen (&lt;b&gt;P&lt;/b&gt;) holt die Region unter der sichtbaren nach vorn. Ein erneuter Klick an derselben Stelle geht tiefer; nach der letzten beginnt es wieder oben. &lt;b&gt;R&lt;/b&gt; setzt die Reihenfolge zurück.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Paint to hide&lt;/h3&gt;&lt;p&gt;With the Paint to Hide tool (&lt;b&gt;H&lt;/b&gt;) paint over regions on the segmentation map: they are hidden and what lies behind shows. The Paint to Hide panel unhides them, &lt;b&gt;Shift+H&lt;/b&gt; all at once.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Zum Ausblenden malen&lt;/h3&gt;&lt;p&gt;Malen Sie mit dem Werkzeug Zum Ausblenden malen (&lt;b&gt;H&lt;/b&gt;) über Regionen auf der Segmentierungskarte: Sie werden ausgeblendet und das Dahinterliegende wird sichtbar. Das Bedienfeld Zum Ausblenden malen blendet sie wieder ein, &lt;b&gt;Umschalt+H&lt;/b&gt; alle auf einmal.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Orbit about a surface point&lt;/h3&gt;&lt;p&gt;With View ▸ Orbit About Surface Point on, an orbit (middle drag, or Alt+left drag) that starts on the model turns about that point, on whatever depth layer is shown there.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Um einen Oberflächenpunkt drehen&lt;/h3&gt;&lt;p&gt;Mit Ansicht ▸ Um Oberflächenpunkt drehen dreht sich eine Drehung (Ziehen mit der mittleren Taste oder Alt+links), die auf dem Modell beginnt, um diesen Punkt, auf welcher Tiefenebene er dort auch gezeigt wird.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Drawing…</source>
        <translation>Wird gezeichnet…</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Keys&lt;/h3&gt;&lt;table cellspacing=&quot;4&quot;&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;B&lt;/b&gt; / &lt;b&gt;E&lt;/b&gt; / &lt;b&gt;G&lt;/b&gt; / &lt;b&gt;I&lt;/b&gt;&lt;/td&gt;&lt;td&gt;brush, eraser, fill, eyedropper (Ctrl+click with any tool)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;H&lt;/b&gt; / &lt;b&gt;P&lt;/b&gt;&lt;/td&gt;&lt;td&gt;paint to hide, pop up&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;L&lt;/b&gt;&lt;/td&gt;&lt;td&gt;layer-aware painting on or off&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;[&lt;/b&gt; &lt;b&gt;]&lt;/b&gt; / Shift+&lt;b&gt;[&lt;/b&gt; &lt;b&gt;]&lt;/b&gt;&lt;/td&gt;&lt;td&gt;brush size / hardness&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;X&lt;/b&gt;&lt;/td&gt;&lt;td&gt;swap foreground and background colours&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;F&lt;/b&gt; / &lt;b&gt;O&lt;/b&gt;&lt;/td&gt;&lt;td&gt;frame the model / orthographic&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Middle drag, Shift+, Ctrl+, wheel&lt;/td&gt;&lt;td&gt;orbit, pan, zoom&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Alt+left / right / middle drag&lt;/td&gt;&lt;td&gt;orbit, zoom, pan (for tablets)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Ctrl+Z&lt;/b&gt; / &lt;b&gt;Ctrl+Shift+Z&lt;/b&gt;&lt;/td&gt;&lt;td&gt;undo / redo&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
        <translation>&lt;h3&gt;Tasten&lt;/h3&gt;&lt;table cellspacing=&quot;4&quot;&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;B&lt;/b&gt; / &lt;b&gt;E&lt;/b&gt; / &lt;b&gt;G&lt;/b&gt; / &lt;b&gt;I&lt;/b&gt;&lt;/td&gt;&lt;td&gt;Pinsel, Radierer, Füllen, Pipette (Strg+Klick mit jedem Werkzeug)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;H&lt;/b&gt; / &lt;b&gt;P&lt;/b&gt;&lt;/td&gt;&lt;td&gt;zum Ausblenden malen, hervorholen&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;L&lt;/b&gt;&lt;/td&gt;&lt;td&gt;ebenenbewusstes Malen ein oder aus&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;[&lt;/b&gt; &lt;b&gt;]&lt;/b&gt; / Umschalt+&lt;b&gt;[&lt;/b&gt; &lt;b&gt;]&lt;/b&gt;&lt;/td&gt;&lt;td&gt;Pinselgröße / Härte&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;X&lt;/b&gt;&lt;/td&gt;&lt;td&gt;Vorder- und Hintergrundfarbe tauschen&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;F&lt;/b&gt; / &lt;b&gt;O&lt;/b&gt;&lt;/td&gt;&lt;td&gt;Modell einpassen / orthografisch&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Ziehen mit der mittleren Taste, Umschalt+, Strg+, Mausrad&lt;/td&gt;&lt;td&gt;drehen, verschieben, zoomen&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Alt+links / rechts / Mitte ziehen&lt;/td&gt;&lt;td&gt;drehen, zoomen, verschieben (für Tablets)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Strg+Z&lt;/b&gt; / &lt;b&gt;Strg+Umschalt+Z&lt;/b&gt;&lt;/td&gt;&lt;td&gt;rückgängig / wiederholen&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</translation>
    </message>
    <message>
        <source>&amp;Show at start</source>
        <translation>Beim &amp;Start zeigen</translation>
    </message>
    <message>
        <source>(no picture)</source>
        <translation>(kein Bild)</translation>
    </message>
</context>
<context>
    <name>ui::RegionGraphPanel</name>
    <message>
        <source>No regions yet</source>
        <translation>Noch keine Regionen</translation>
    </message>
    <message>
        <source>No regions in this view</source>
        <translation>Keine Regionen in dieser Ansicht</translation>
    </message>
    <message>
        <source>Regions: %1, connections: %2</source>
        <translation>Regionen: %1, Verbindungen: %2</translation>
    </message>
    <message>
        <source>Small regions merged into grey nodes: %1</source>
        <translation>Zu grauen Knoten zusammengefasste kleine Regionen: %1</translation>
    </message>
    <message>
        <source>Depth layer %1</source>
        <translation>Tiefenebene %1</translation>
    </message>
    <message>
        <source>%1 small regions of depth layer %2
%3 pixels together</source>
        <translation>%1 kleine Regionen der Tiefenebene %2
zusammen %3 Pixel</translation>
    </message>
    <message>
        <source>+%1</source>
        <translation>+%1</translation>
    </message>
    <message>
        <source>Region %1 on depth layer %2
%3 pixels
Connected regions: %4</source>
        <translation>Region %1 auf Tiefenebene %2
%3 Pixel
Verbundene Regionen: %4</translation>
    </message>
    <message>
        <source>%1 pixel links</source>
        <translation>%1 Pixelverbindungen</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Einpassen</translation>
    </message>
    <message>
        <source>Show the whole graph (F or Home in the graph). The wheel zooms, dragging the background pans.</source>
        <translation>Den ganzen Graphen zeigen (F oder Pos1 im Graphen). Das Mausrad zoomt, Ziehen auf dem Hintergrund verschiebt.</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source>All sizes</source>
        <translation>Alle Größen</translation>
    </message>
    <message>
        <source>Hide regions smaller than this many pixels</source>
        <translation>Regionen mit weniger Pixeln ausblenden</translation>
    </message>
    <message>
        <source>&amp;Hide under:</source>
        <translation>&amp;Ausblenden unter:</translation>
    </message>
    <message>
        <source>&amp;Neighbours only</source>
        <translation>Nur &amp;Nachbarn</translation>
    </message>
    <message>
        <source>Show only the selected region (click a node) and the regions connected to it</source>
        <translation>Nur die gewählte Region (Knoten anklicken) und die mit ihr verbundenen Regionen zeigen</translation>
    </message>
    <message>
        <source>Click a node to see its neighbours only</source>
        <translation>Einen Knoten anklicken, um nur seine Nachbarn zu sehen</translation>
    </message>
    <message>
        <source>Shown: %1 (filtered out: %2), in grey nodes: %3</source>
        <translation>Gezeigt: %1 (ausgefiltert: %2), in grauen Knoten: %3</translation>
    </message>
</context>
<context>
    <name>ui::RegionTools</name>
    <message>
        <source>&amp;Automatic Pop-up</source>
        <translation>&amp;Automatisch hervorholen</translation>
    </message>
    <message>
        <source>While painting layer-aware, bring the surface under the brush to the front when it goes behind another</source>
        <translation>Beim ebenenbewussten Malen die Fläche unter dem Pinsel nach vorn holen, wenn sie hinter eine andere gerät</translation>
    </message>
    <message>
        <source>&amp;See-Through Pop-ups</source>
        <translation>Hervorgeholte Regionen &amp;durchscheinend</translation>
    </message>
    <message>
        <source>Draw popped-up and revealed regions half transparent, so what surrounds them stays visible</source>
        <translation>Hervorgeholte und freigelegte Regionen halb durchsichtig zeichnen, damit ihre Umgebung sichtbar bleibt</translation>
    </message>
    <message>
        <source>Orbit About &amp;Surface Point</source>
        <translation>Um Oberflächen&amp;punkt drehen</translation>
    </message>
    <message>
        <source>Start an orbit on the model to turn about that point, on whatever depth layer is shown there</source>
        <translation>Eine auf dem Modell begonnene Drehung kreist um diesen Punkt, auf welcher Tiefenebene er auch gezeigt wird</translation>
    </message>
    <message>
        <source>&amp;Reset Region Order</source>
        <translation>Regionsreihenfolge &amp;zurücksetzen</translation>
    </message>
    <message>
        <source>Show the regions in their original order (depth layer 1 in front)</source>
        <translation>Die Regionen in ihrer ursprünglichen Reihenfolge zeigen (Tiefenebene 1 vorn)</translation>
    </message>
    <message>
        <source>Reset the region order (R)</source>
        <translation>Die Regionsreihenfolge zurücksetzen (R)</translation>
    </message>
    <message>
        <source>U&amp;nhide All Regions</source>
        <translation>Alle Regionen ei&amp;nblenden</translation>
    </message>
    <message>
        <source>Show every hidden region again (Shift+H)</source>
        <translation>Alle ausgeblendeten Regionen wieder zeigen (Umschalt+H)</translation>
    </message>
    <message>
        <source>Nothing to pop up here</source>
        <translation>Hier gibt es nichts hervorzuholen</translation>
    </message>
    <message>
        <source>Region %1 (depth layer %2) in front; click again to go deeper</source>
        <translation>Region %1 (Tiefenebene %2) vorn; erneut klicken, um tiefer zu gehen</translation>
    </message>
    <message numerus="yes">
        <source>%n region(s) hidden</source>
        <translation>
            <numerusform>%n Region ausgeblendet</numerusform>
            <numerusform>%n Regionen ausgeblendet</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ui::ScriptActions</name>
    <message>
        <source>the script&apos;s view (%1×%2) is not the window&apos;s (%3×%4); replay it with layerpaint-cli</source>
        <translation>die Ansicht des Skripts (%1×%2) ist nicht die des Fensters (%3×%4); spielen Sie es mit layerpaint-cli ab</translation>
    </message>
    <message>
        <source>the depth layers of this view cannot be built</source>
        <translation>die Tiefenebenen dieser Ansicht können nicht erstellt werden</translation>
    </message>
    <message>
        <source>Run &amp;Script…</source>
        <translation>&amp;Skript ausführen…</translation>
    </message>
    <message>
        <source>Replay a script of painting operations on the open model</source>
        <translation>Ein Skript aus Malvorgängen auf dem geöffneten Modell abspielen</translation>
    </message>
    <message>
        <source>Copy Session as &amp;Script</source>
        <translation>Sitzung als &amp;Skript kopieren</translation>
    </message>
    <message>
        <source>Copy what you did since opening the model as a script that reproduces it (for bug reports and automation)</source>
        <translation>Was Sie seit dem Öffnen des Modells getan haben, als Skript kopieren, das es wiederholt (für Fehlerberichte und Automatisierung)</translation>
    </message>
    <message numerus="yes">
        <source>Copied %n operation(s) as a script</source>
        <translation>
            <numerusform>%n Vorgang als Skript kopiert</numerusform>
            <numerusform>%n Vorgänge als Skript kopiert</numerusform>
        </translation>
    </message>
    <message>
        <source>Run Script</source>
        <translation>Skript ausführen</translation>
    </message>
    <message>
        <source>Scripts (*.json);;All files (*)</source>
        <translation>Skripte (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>The script cannot be run: %1</source>
        <translation>Das Skript kann nicht ausgeführt werden: %1</translation>
    </message>
    <message numerus="yes">
        <source>Run %n operation(s) of %1 on the open model?</source>
        <translation>
            <numerusform>%n Vorgang aus %1 auf dem geöffneten Modell ausführen?</numerusform>
            <numerusform>%n Vorgänge aus %1 auf dem geöffneten Modell ausführen?</numerusform>
        </translation>
    </message>
    <message>
        <source>As &amp;One Undo Step</source>
        <translation>Als &amp;ein Rückgängig-Schritt</translation>
    </message>
    <message>
        <source>&amp;Step by Step</source>
        <translation>&amp;Schritt für Schritt</translation>
    </message>
    <message>
        <source>Running the script…</source>
        <translation>Das Skript wird ausgeführt…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message numerus="yes">
        <source>cancelled after %n operation(s)</source>
        <translation>
            <numerusform>nach %n Vorgang abgebrochen</numerusform>
            <numerusform>nach %n Vorgängen abgebrochen</numerusform>
        </translation>
    </message>
    <message>
        <source>Script finished</source>
        <translation>Skript beendet</translation>
    </message>
    <message>
        <source>Script stopped: %1</source>
        <translation>Skript angehalten: %1</translation>
    </message>
</context>
<context>
    <name>ui::SegmentationControls</name>
    <message>
        <source>Depth threshold</source>
        <translation>Tiefenschwelle</translation>
    </message>
    <message>
        <source>How far apart in depth two neighbouring pixels may be and still count as one surface, as a fraction of the model&apos;s longest side.
Smaller splits the view into more regions.</source>
        <translation>Wie weit zwei benachbarte Pixel in der Tiefe auseinanderliegen dürfen und noch als eine Fläche gelten, als Anteil der längsten Seite des Modells.
Kleiner zerlegt die Ansicht in mehr Regionen.</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <source>Back to the default threshold (%1)</source>
        <translation>Zurück zur Standardschwelle (%1)</translation>
    </message>
    <message>
        <source>Surface</source>
        <translation>Fläche</translation>
    </message>
    <message>
        <source>Plain depth</source>
        <translation>Reine Tiefe</translation>
    </message>
    <message>
        <source>Follows each triangle&apos;s plane: sloped surfaces stay one region at any threshold</source>
        <translation>Folgt der Ebene jedes Dreiecks: geneigte Flächen bleiben bei jeder Schwelle eine Region</translation>
    </message>
    <message>
        <source>The paper&apos;s test: depth difference below the threshold; steep surfaces break apart</source>
        <translation>Der Test aus dem Artikel: Tiefenunterschied unter der Schwelle; steile Flächen zerfallen</translation>
    </message>
    <message>
        <source>How neighbouring pixels are judged to lie on one surface</source>
        <translation>Wie entschieden wird, ob benachbarte Pixel auf einer Fläche liegen</translation>
    </message>
    <message>
        <source>Capture back faces (two-sided)</source>
        <translation>Rückseiten erfassen (zweiseitig)</translation>
    </message>
    <message>
        <source>Show, paint and split into depth layers the back faces of every surface. Without it, back faces are hidden but for the open surfaces of double-sided materials (a leaf, a cloth). Changing it captures the view again.</source>
        <translation>Die Rückseiten aller Flächen zeigen, bemalen und in Tiefenebenen zerlegen. Ohne diese Option bleiben Rückseiten verborgen, außer bei offenen Flächen doppelseitiger Materialien (ein Blatt, ein Tuch). Eine Änderung erfasst die Ansicht neu.</translation>
    </message>
    <message>
        <source>Threshold:</source>
        <translation>Schwelle:</translation>
    </message>
    <message>
        <source>Test:</source>
        <translation>Test:</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automatisch</translation>
    </message>
    <message>
        <source>C++ (processor)</source>
        <translation>C++ (Prozessor)</translation>
    </message>
    <message>
        <source>Compute shader (graphics card)</source>
        <translation>Compute-Shader (Grafikkarte)</translation>
    </message>
    <message>
        <source>Where pixel connectivity is computed; both give the same result, Automatic picks the faster for this computer</source>
        <translation>Wo die Pixel-Konnektivität berechnet wird; beide liefern dasselbe Ergebnis, Automatisch wählt das auf diesem Rechner Schnellere</translation>
    </message>
    <message>
        <source>Connectivity:</source>
        <translation>Konnektivität:</translation>
    </message>
    <message>
        <source>Automatic (%1)</source>
        <translation>Automatisch (%1)</translation>
    </message>
</context>
<context>
    <name>ui::StabilizerBox</name>
    <message>
        <source>Stroke sta&amp;bilizer</source>
        <translation>Strich-&amp;Stabilisator</translation>
    </message>
    <message>
        <source>The brush follows the pointer on a string: small wobbles never reach the stroke, for pen and mouse alike</source>
        <translation>Der Pinsel folgt dem Zeiger an einer Schnur: kleines Zittern erreicht den Strich nie, mit Stift wie mit Maus</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source>Length of the string: how far the pointer moves before the brush follows</source>
        <translation>Länge der Schnur: wie weit sich der Zeiger bewegt, bevor der Pinsel folgt</translation>
    </message>
    <message>
        <source>Len&amp;gth</source>
        <translation>&amp;Länge</translation>
    </message>
    <message>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <source>Averages the pointer&apos;s positions before the string pulls: 0 takes each as it comes</source>
        <translation>Mittelt die Zeigerpositionen, bevor die Schnur zieht: 0 nimmt jede, wie sie kommt</translation>
    </message>
    <message>
        <source>Smoothi&amp;ng</source>
        <translation>Glä&amp;ttung</translation>
    </message>
    <message>
        <source>C&amp;atch up at release</source>
        <translation>Beim Loslassen &amp;nachziehen</translation>
    </message>
    <message>
        <source>On release the stroke goes on to where the pointer is; off, it ends where the brush was</source>
        <translation>Beim Loslassen führt der Strich bis zum Zeiger weiter; sonst endet er, wo der Pinsel war</translation>
    </message>
</context>
<context>
    <name>ui::SymmetryBox</name>
    <message>
        <source>Symmetry</source>
        <translation>Symmetrie</translation>
    </message>
    <message>
        <source>Every dab is repeated on the mirrored or turned surface, also where that side is hidden or faces away in this view</source>
        <translation>Jeder Tupfer wird auf der gespiegelten oder gedrehten Oberfläche wiederholt, auch wo diese Seite in dieser Ansicht verdeckt oder abgewandt ist</translation>
    </message>
    <message>
        <source>&amp;X</source>
        <translation>&amp;X</translation>
    </message>
    <message>
        <source>Y</source>
        <translation>Y</translation>
    </message>
    <message>
        <source>Z</source>
        <translation>Z</translation>
    </message>
    <message>
        <source>Mirror across the model&apos;s plane across this axis</source>
        <translation>An der Ebene des Modells quer zu dieser Achse spiegeln</translation>
    </message>
    <message>
        <source>Mirror</source>
        <translation>Spiegeln</translation>
    </message>
    <message>
        <source>Bounding-box centre</source>
        <translation>Mitte des Begrenzungsquaders</translation>
    </message>
    <message>
        <source>Origin</source>
        <translation>Ursprung</translation>
    </message>
    <message>
        <source>Where the mirror planes and the radial axis pass through</source>
        <translation>Wodurch die Spiegelebenen und die radiale Achse verlaufen</translation>
    </message>
    <message>
        <source>Centre</source>
        <translation>Mitte</translation>
    </message>
    <message>
        <source>Copies turned about the axis, the stroke included; 1 for none</source>
        <translation>Um die Achse gedrehte Kopien, den Strich eingeschlossen; 1 für keine</translation>
    </message>
    <message>
        <source>X axis</source>
        <translation>X-Achse</translation>
    </message>
    <message>
        <source>Y axis</source>
        <translation>Y-Achse</translation>
    </message>
    <message>
        <source>Z axis</source>
        <translation>Z-Achse</translation>
    </message>
    <message>
        <source>Radial</source>
        <translation>Radial</translation>
    </message>
</context>
<context>
    <name>ui::TextureExportDialog</name>
    <message>
        <source>Export Textures</source>
        <translation>Texturen exportieren</translation>
    </message>
    <message>
        <source>&amp;Preset:</source>
        <translation>&amp;Vorgabe:</translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation>&amp;Durchsuchen…</translation>
    </message>
    <message>
        <source>&amp;Folder:</source>
        <translation>&amp;Ordner:</translation>
    </message>
    <message>
        <source>F&amp;ormat:</source>
        <translation>F&amp;ormat:</translation>
    </message>
    <message>
        <source>&amp;Bit depth:</source>
        <translation>&amp;Bittiefe:</translation>
    </message>
    <message>
        <source>&amp;Normal map:</source>
        <translation>&amp;Normal-Map:</translation>
    </message>
    <message>
        <source>Pa&amp;dding:</source>
        <translation>&amp;Randauffüllung:</translation>
    </message>
    <message>
        <source>&amp;Size:</source>
        <translation>&amp;Größe:</translation>
    </message>
    <message>
        <source>Files to write:</source>
        <translation>Zu schreibende Dateien:</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Exportieren</translation>
    </message>
    <message>
        <source>glTF metallic-roughness</source>
        <translation>glTF Metallic-Roughness</translation>
    </message>
    <message>
        <source>Unreal Engine</source>
        <translation>Unreal Engine</translation>
    </message>
    <message>
        <source>Unity (URP, HDRP)</source>
        <translation>Unity (URP, HDRP)</translation>
    </message>
    <message>
        <source>ORM (Godot, Blender)</source>
        <translation>ORM (Godot, Blender)</translation>
    </message>
    <message>
        <source>From a Preset File…</source>
        <translation>Aus einer Vorgabedatei…</translation>
    </message>
    <message>
        <source>PNG</source>
        <translation>PNG</translation>
    </message>
    <message>
        <source>TIFF</source>
        <translation>TIFF</translation>
    </message>
    <message>
        <source>OpenEXR</source>
        <translation>OpenEXR</translation>
    </message>
    <message>
        <source>TGA</source>
        <translation>TGA</translation>
    </message>
    <message>
        <source>OpenGL (Y up: glTF, Unity, Godot, Blender)</source>
        <translation>OpenGL (Y nach oben: glTF, Unity, Godot, Blender)</translation>
    </message>
    <message>
        <source>DirectX (Y down: Unreal Engine)</source>
        <translation>DirectX (Y nach unten: Unreal Engine)</translation>
    </message>
    <message>
        <source> texels</source>
        <translation> Texel</translation>
    </message>
    <message>
        <source>How far the colours at the edges of the UV charts are grown into the empty space, so that mipmaps show no seams</source>
        <translation>Wie weit die Farben an den Rändern der UV-Inseln in den leeren Raum wachsen, damit Mipmaps keine Nähte zeigen</translation>
    </message>
    <message>
        <source>Fill all empty space</source>
        <translation>Den ganzen leeren Raum füllen</translation>
    </message>
    <message>
        <source>Each texture set&apos;s own</source>
        <translation>Die jedes Texturensatzes</translation>
    </message>
    <message>
        <source>%1 × %1</source>
        <translation>%1 × %1</translation>
    </message>
    <message>
        <source>16-bit float (half)</source>
        <translation>16-Bit-Gleitkomma (half)</translation>
    </message>
    <message>
        <source>32-bit float</source>
        <translation>32-Bit-Gleitkomma</translation>
    </message>
    <message>
        <source>8-bit</source>
        <translation>8 Bit</translation>
    </message>
    <message>
        <source>16-bit</source>
        <translation>16 Bit</translation>
    </message>
    <message>
        <source>The model has no texture set to export: it is painted with vertex colours.</source>
        <translation>Das Modell hat keinen Texturensatz zum Exportieren: es wird mit Vertexfarben bemalt.</translation>
    </message>
    <message>
        <source>Choose the folder to write the files into.</source>
        <translation>Wählen Sie den Ordner, in den die Dateien geschrieben werden.</translation>
    </message>
    <message>
        <source>Export Textures To</source>
        <translation>Texturen exportieren nach</translation>
    </message>
    <message>
        <source>Texture Export Preset</source>
        <translation>Texturexport-Vorgabe</translation>
    </message>
    <message>
        <source>Export presets (*.json)</source>
        <translation>Exportvorgaben (*.json)</translation>
    </message>
</context>
<context>
    <name>ui::UnitSpinBox</name>
    <message>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
</context>
<context>
    <name>ui::Viewport</name>
    <message>
        <source>The depth-layer capture is not available.</source>
        <translation>Die Tiefenebenenerfassung ist nicht verfügbar.</translation>
    </message>
    <message>
        <source>LayerPaint needs OpenGL 4.5, but this system provides OpenGL %1.%2.</source>
        <translation>LayerPaint benötigt OpenGL 4.5, dieses System bietet aber OpenGL %1.%2.</translation>
    </message>
    <message>
        <source>The renderer could not start: %1</source>
        <translation>Der Renderer konnte nicht starten: %1</translation>
    </message>
    <message>
        <source>The depth-layer views could not start: %1</source>
        <translation>Die Tiefenebenenansichten konnten nicht starten: %1</translation>
    </message>
    <message>
        <source>The depth layers cannot be shown: %1</source>
        <translation>Die Tiefenebenen können nicht angezeigt werden: %1</translation>
    </message>
    <message>
        <source>Roughness</source>
        <translation>Rauheit</translation>
    </message>
    <message>
        <source>Metallic</source>
        <translation>Metallisch</translation>
    </message>
    <message>
        <source>Mask (black hides, white shows)</source>
        <translation>Maske (Schwarz verbirgt, Weiß zeigt)</translation>
    </message>
    <message>
        <source>Preparing the model for display…</source>
        <translation>Das Modell wird zur Anzeige vorbereitet…</translation>
    </message>
    <message>
        <source>The model cannot be drawn: there is not enough memory for its GL buffers.</source>
        <translation>Das Modell kann nicht gezeichnet werden: Für seine GL-Puffer reicht der Speicher nicht.</translation>
    </message>
</context>
</TS>

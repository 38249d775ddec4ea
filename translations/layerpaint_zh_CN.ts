<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>main</name>
    <message>
        <source>Layer-aware 3D painting of meshes.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The model to open (glTF, OBJ, PLY, STL, OFF, ... or builtin:NAME). Without it the trefoil knot opens.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>[file]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Where pixel connectivity is computed: auto (the faster here), cpu or gpu.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ui::BrushToolBar</name>
    <message>
        <source>Brush</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Brush colour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Radius</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> px</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Brush radius on screen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Hardness</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>0: soft falloff from the centre, 100: a hard edge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>O&amp;pacity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The most one stroke covers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paint &amp;into</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Where paint goes: a texture (meshes with UVs) or vertex colours. Changing it starts the painting afresh.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Texture %1 × %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Vertex colours</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Brush Colour</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ui::FillPanel</name>
    <message>
        <source>Region under the cursor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connected surface</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Similar colour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The segmented region clicked in this view, including the part of it hidden behind other surfaces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Everything connected to the clicked surface in the mesh, seen or not, from any side</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The surface around the clicked point whose colour is within the tolerance of the colour there</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What a click with the Fill tool fills</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Colour tolerance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How far a colour may differ from the clicked one and still be filled (in any channel): 0 % takes only the very same colour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Fill:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Tolerance:</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ui::LayersPanel</name>
    <message>
        <source>Layers appear when the view stays still.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Click a layer to see it alone; “All layers” shows the whole view.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All layers
Layers: %1
Regions: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The whole view, front to back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Layer %1
Fragments: %2
Regions: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show layer %1 alone</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ui::MainWindow</name>
    <message>
        <source>LayerPaint</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OpenGL Error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The 3D view cannot be shown.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not build the layers: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Trefoil knot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hexagonal ring</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Row of four</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Segmentation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Layers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Region Graph</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Region %1 selected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Shaded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the model shaded, all layers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Single &amp;Layer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show one depth layer alone (choose it in the Layers panel)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Se&amp;gmentation Map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Colour every region of the visible layer differently</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Region &amp;Boundaries</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Outline where a surface is not connected to its neighbours on the same layer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Building layers…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Layers: %1 · Fragments: %2 · Regions: %3 · Built in %4 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>build_layers of this view:
capture %1 ms (drawing), %2 ms (sorting)
connectivity %3 ms, regions %4 ms
%5 ms from the capture to the picture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New from &amp;Built-in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Frame All</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Orthographic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Panels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;About LayerPaint</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;%1 %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No Recent Files</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Clear Menu</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>3D models (*.gltf *.glb *.obj *.ply *.stl *.off)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>glTF 2.0 (*.gltf *.glb)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wavefront OBJ (*.obj)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stanford PLY (*.ply)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>STL (*.stl)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Object File Format (*.off)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open Model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About LayerPaint</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;h3&gt;LayerPaint %1&lt;/h3&gt;&lt;p&gt;Layer-aware 3D painting: paint surfaces hidden behind others in one stroke.&lt;/p&gt;&lt;p&gt;License: GNU GPL version 3 or later.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — LayerPaint</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not open %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open Failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not open “%1”.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opening %1 cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opening %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opening Model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — %2 vertices, %3 triangles</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s) while loading: %1</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Layer-Aware Painting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Layer-aware painting (L): strokes follow a surface behind whatever covers it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paint across depth layers; off: only the front-most surface is paintable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Layer-aware painting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Conventional painting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show &amp;Brush Maps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>While painting, show the paintable (red) and trackable (blue) pixels around the brush</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot paint this model: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot paint: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paint Stroke</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change Paint Target</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Painting into another target starts afresh: the painting so far and its undo history are discarded.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot paint into that target: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Paint</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>compute shader</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>C++</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fill</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tools</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Brush</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paint strokes with the brush</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Eraser</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Erase paint back to the model&apos;s original colours</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Fill</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Flood fill with the brush colour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>E&amp;yedropper</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pick the surface colour under the cursor (or Ctrl+click)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paint to &amp;Hide</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hide every region the brush touches, revealing what lies behind</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Pop Up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bring the region below the visible one to the front (or Shift+click); click again to cycle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot fill: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Filled in %1 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing to fill there</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ui::RegionGraphPanel</name>
    <message>
        <source>No regions yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No regions in this view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Regions: %1, connections: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Small regions merged into grey nodes: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Layer %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 small regions of layer %2
%3 pixels together</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>+%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Region %1 on layer %2
%3 pixels
Connected regions: %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 pixel links</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ui::SegmentationControls</name>
    <message>
        <source>Depth threshold</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How far apart in depth two neighbouring pixels may be and still count as one surface, as a fraction of the model&apos;s longest side.
Smaller splits the view into more regions.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back to the default threshold (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Surface</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plain depth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Follows each triangle&apos;s plane: sloped surfaces stay one region at any threshold</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The paper&apos;s test: depth difference below the threshold; steep surfaces break apart</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How neighbouring pixels are judged to lie on one surface</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Capture back faces (two-sided)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Also split the inside of open or single-sided surfaces into layers. Changing it captures the view again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Threshold:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Test:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>C++ (processor)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compute shader (graphics card)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Where pixel connectivity is computed; both give the same result, Automatic picks the faster for this computer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connectivity:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Automatic (%1)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ui::Viewport</name>
    <message>
        <source>The layer capture is not available.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>LayerPaint needs OpenGL 4.5, but this system provides OpenGL %1.%2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The renderer could not start: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The layer views could not start: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The layers cannot be shown: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>

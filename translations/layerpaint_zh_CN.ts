<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>BrushPresetsPanel</name>
    <message>
        <source>Soft Round</source>
        <translation>柔和圆形</translation>
    </message>
    <message>
        <source>Hard Ink</source>
        <translation>硬墨水</translation>
    </message>
    <message>
        <source>Chalk</source>
        <translation>粉笔</translation>
    </message>
    <message>
        <source>Spatter</source>
        <translation>喷溅</translation>
    </message>
    <message>
        <source>Metal Paint</source>
        <translation>金属漆</translation>
    </message>
    <message>
        <source>Rough Matte</source>
        <translation>粗糙哑光</translation>
    </message>
    <message>
        <source>Eraser Soft</source>
        <translation>柔和橡皮擦</translation>
    </message>
    <message>
        <source>Stabilized Liner</source>
        <translation>稳定勾线笔</translation>
    </message>
</context>
<context>
    <name>ToolHints</name>
    <message>
        <source>Brush: drag to paint; Shift+click draws a straight line on from the last stroke; Ctrl+click picks a colour; Alt+drag moves the camera</source>
        <translation>画笔：拖动绘画；Shift+单击从上一笔画出直线；Ctrl+单击拾取颜色；Alt+拖动移动相机</translation>
    </message>
    <message>
        <source>Eraser: drag to bring back the original surface; Shift+click erases a straight line; Alt+drag moves the camera</source>
        <translation>橡皮擦：拖动恢复原始表面；Shift+单击擦除一条直线；Alt+拖动移动相机</translation>
    </message>
    <message>
        <source>Fill: click to fill with the brush colour (options in the Fill panel); Ctrl+click picks a colour</source>
        <translation>填充：单击用画笔颜色填充（选项在填充面板中）；Ctrl+单击拾取颜色</translation>
    </message>
    <message>
        <source>Eyedropper: click to take the painted colour of the surface under the cursor</source>
        <translation>吸管：单击拾取光标下表面的绘制颜色</translation>
    </message>
    <message>
        <source>Paint to Hide: paint over regions to hide them and see what lies behind; Shift+H unhides all</source>
        <translation>绘制隐藏：在区域上绘制以隐藏它们并看到后面的内容；Shift+H 全部取消隐藏</translation>
    </message>
    <message>
        <source>Pop Up: click to bring the region below the visible one to the front; click again to go deeper (Ctrl+Shift+click with any tool)</source>
        <translation>弹出：单击将可见区域下方的区域移到最前；再次单击则更深入（任何工具下 Ctrl+Shift+单击）</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Layer-aware 3D painting of meshes.</source>
        <translation>对网格进行图层感知的三维绘画。</translation>
    </message>
    <message>
        <source>file</source>
        <translation>文件</translation>
    </message>
    <message>
        <source>[file]</source>
        <translation>[文件]</translation>
    </message>
    <message>
        <source>Where pixel connectivity is computed: auto (the faster here), cpu or gpu.</source>
        <translation>像素连通性的计算位置：auto（在本机上更快的一种）、cpu 或 gpu。</translation>
    </message>
    <message>
        <source>The project or model to open (glTF, OBJ, PLY, STL, OFF, ... or builtin:NAME). Without it the trefoil knot opens.</source>
        <translation>要打开的项目或模型（glTF、OBJ、PLY、STL、OFF……或 builtin:NAME）。不指定时打开三叶结。</translation>
    </message>
</context>
<context>
    <name>ui::BackgroundTask</name>
    <message>
        <source>Not enough memory.</source>
        <translation>内存不足。</translation>
    </message>
</context>
<context>
    <name>ui::BrushPanel</name>
    <message>
        <source>&amp;Radius</source>
        <translation>半径(&amp;R)</translation>
    </message>
    <message>
        <source> px</source>
        <translation> 像素</translation>
    </message>
    <message>
        <source>Brush radius on screen ([ and ] change it)</source>
        <translation>画笔在屏幕上的半径（[ 和 ] 可调整）</translation>
    </message>
    <message>
        <source>&amp;Hardness</source>
        <translation>硬度(&amp;H)</translation>
    </message>
    <message>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <source>0: soft falloff from the centre, 100: a hard edge (Shift+[ and Shift+])</source>
        <translation>0：从中心柔和衰减，100：硬边（Shift+[ 和 Shift+]）</translation>
    </message>
    <message>
        <source>O&amp;pacity</source>
        <translation>不透明度(&amp;P)</translation>
    </message>
    <message>
        <source>The most one stroke covers</source>
        <translation>一笔最多能达到的覆盖程度</translation>
    </message>
    <message>
        <source>&amp;Flow</source>
        <translation>流量(&amp;F)</translation>
    </message>
    <message>
        <source>How much one dab adds towards the opacity</source>
        <translation>每个笔触点向不透明度增加的量</translation>
    </message>
    <message>
        <source>&amp;Spacing</source>
        <translation>间距(&amp;S)</translation>
    </message>
    <message>
        <source>Distance between dabs, in per cent of the radius</source>
        <translation>笔触点之间的距离，以半径的百分比表示</translation>
    </message>
    <message>
        <source>R_max: how far a layer-aware stroke looks for the surface it follows from one dab to the next; 0 chooses it from the radius</source>
        <translation>R_max：图层感知笔画从一个笔触点到下一个笔触点时查找所跟随表面的范围；0 表示根据半径自动选择</translation>
    </message>
    <message>
        <source>&amp;Tracking (R_max)</source>
        <translation>跟踪范围 (R_max)(&amp;T)</translation>
    </message>
    <message>
        <source>Si&amp;ze</source>
        <translation>大小(&amp;Z)</translation>
    </message>
    <message>
        <source>Pen pressure scales the radius</source>
        <translation>笔压缩放半径</translation>
    </message>
    <message>
        <source>Opa&amp;city</source>
        <translation>不透明度(&amp;C)</translation>
    </message>
    <message>
        <source>Pen pressure scales the opacity</source>
        <translation>笔压缩放不透明度</translation>
    </message>
    <message>
        <source>Pressure changes</source>
        <translation>压力影响</translation>
    </message>
    <message>
        <source>Pressure curve: left, a light touch gives much; right, it takes a firm press</source>
        <translation>压力曲线：向左轻触即可产生较大效果；向右需要用力按压</translation>
    </message>
    <message>
        <source>Pressure c&amp;urve</source>
        <translation>压力曲线(&amp;U)</translation>
    </message>
    <message>
        <source>γ %1</source>
        <translation>γ %1</translation>
    </message>
    <message>
        <source>Automatic (%1 px)</source>
        <translation>自动（%1 像素）</translation>
    </message>
    <message>
        <source>Base co&amp;lour</source>
        <translation>基础颜色(&amp;L)</translation>
    </message>
    <message>
        <source>Strokes paint the base colour (the Colour panel&apos;s)</source>
        <translation>笔画绘制基础颜色（颜色面板中的颜色）</translation>
    </message>
    <message>
        <source>R&amp;oughness</source>
        <translation>粗糙度(&amp;O)</translation>
    </message>
    <message>
        <source>Strokes paint this roughness (0: glossy, 1: matt)</source>
        <translation>笔画绘制此粗糙度（0：光滑，1：哑光）</translation>
    </message>
    <message>
        <source>&amp;Metallic</source>
        <translation>金属度(&amp;M)</translation>
    </message>
    <message>
        <source>Strokes paint this metalness (0: dielectric, 1: metal)</source>
        <translation>笔画绘制此金属度（0：非金属，1：金属）</translation>
    </message>
</context>
<context>
    <name>ui::BrushPresetsPanel</name>
    <message>
        <source>New from Current</source>
        <translation>从当前新建</translation>
    </message>
    <message>
        <source>Save the current brush as a preset</source>
        <translation>将当前画笔保存为预设</translation>
    </message>
    <message>
        <source>Rename</source>
        <translation>重命名</translation>
    </message>
    <message>
        <source>Rename the chosen preset</source>
        <translation>重命名所选预设</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>删除</translation>
    </message>
    <message>
        <source>Delete the chosen preset</source>
        <translation>删除所选预设</translation>
    </message>
    <message>
        <source>Import…</source>
        <translation>导入…</translation>
    </message>
    <message>
        <source>Add a preset from a .lpbrush file</source>
        <translation>从 .lpbrush 文件添加预设</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>导出…</translation>
    </message>
    <message>
        <source>Write the chosen preset to a .lpbrush file</source>
        <translation>将所选预设写入 .lpbrush 文件</translation>
    </message>
    <message>
        <source>%1: cannot be opened (%2)</source>
        <translation>%1：无法打开（%2）</translation>
    </message>
    <message>
        <source>%1: too large for a brush preset</source>
        <translation>%1：作为画笔预设过大</translation>
    </message>
    <message>
        <source>%1: cannot be written (%2)</source>
        <translation>%1：无法写入（%2）</translation>
    </message>
    <message>
        <source>New Brush Preset</source>
        <translation>新建画笔预设</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>名称：</translation>
    </message>
    <message>
        <source>My Brush</source>
        <translation>我的画笔</translation>
    </message>
    <message>
        <source>Import Brush Preset</source>
        <translation>导入画笔预设</translation>
    </message>
    <message>
        <source>Brush presets (*.lpbrush);;All files (*)</source>
        <translation>画笔预设 (*.lpbrush);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Export Brush Preset</source>
        <translation>导出画笔预设</translation>
    </message>
    <message>
        <source>Brush presets (*.lpbrush)</source>
        <translation>画笔预设 (*.lpbrush)</translation>
    </message>
</context>
<context>
    <name>ui::BrushTipBox</name>
    <message>
        <source>Round</source>
        <translation>圆形</translation>
    </message>
    <message>
        <source>Round soft</source>
        <translation>柔和圆形</translation>
    </message>
    <message>
        <source>Round hard</source>
        <translation>硬边圆形</translation>
    </message>
    <message>
        <source>Square</source>
        <translation>方形</translation>
    </message>
    <message>
        <source>Spatter</source>
        <translation>飞溅</translation>
    </message>
    <message>
        <source>Chalk</source>
        <translation>粉笔</translation>
    </message>
    <message>
        <source>Bristle</source>
        <translation>鬃毛</translation>
    </message>
    <message>
        <source>Star</source>
        <translation>星形</translation>
    </message>
    <message>
        <source>Noise</source>
        <translation>噪点</translation>
    </message>
    <message>
        <source>Brush tip</source>
        <translation>笔尖</translation>
    </message>
    <message>
        <source>The tip&apos;s shape: every channel painted is weighted by it</source>
        <translation>笔尖的形状：绘制的每个通道都按它加权</translation>
    </message>
    <message>
        <source>Load T&amp;ip…</source>
        <translation>载入笔尖(&amp;I)…</translation>
    </message>
    <message>
        <source>Use a PNG or TIFF image as the tip (dark paints); it is kept in the project</source>
        <translation>使用 PNG 或 TIFF 图像作为笔尖（深色处绘制）；它保存在项目中</translation>
    </message>
    <message>
        <source>Fixed</source>
        <translation>固定</translation>
    </message>
    <message>
        <source>Follow the stroke</source>
        <translation>跟随笔画</translation>
    </message>
    <message>
        <source>Random</source>
        <translation>随机</translation>
    </message>
    <message>
        <source>How the tip is turned: by the angle, along the stroke&apos;s direction plus the angle, or at random per dab</source>
        <translation>笔尖如何旋转：按角度、沿笔画方向加角度，或每个笔触随机</translation>
    </message>
    <message>
        <source>Tip tur&amp;n</source>
        <translation>笔尖旋转(&amp;N)</translation>
    </message>
    <message>
        <source>&amp;Angle</source>
        <translation>角度(&amp;A)</translation>
    </message>
    <message>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <source>The tip&apos;s turn, clockwise</source>
        <translation>笔尖的旋转，顺时针</translation>
    </message>
    <message>
        <source>Size &amp;jitter</source>
        <translation>大小抖动(&amp;J)</translation>
    </message>
    <message>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <source>Each dab is up to this much smaller, at random</source>
        <translation>每个笔触随机缩小至多这么多</translation>
    </message>
    <message>
        <source>Opacit&amp;y jitter</source>
        <translation>不透明度抖动(&amp;Y)</translation>
    </message>
    <message>
        <source>Each dab is up to this much more transparent, at random</source>
        <translation>每个笔触随机更透明至多这么多</translation>
    </message>
    <message>
        <source>An&amp;gle jitter</source>
        <translation>角度抖动(&amp;G)</translation>
    </message>
    <message>
        <source>Each dab turns up to this far either way, at random</source>
        <translation>每个笔触随机向任一方向旋转至多这么多</translation>
    </message>
    <message>
        <source>Scatt&amp;er</source>
        <translation>散布(&amp;E)</translation>
    </message>
    <message>
        <source>Each dab moves up to this far from the stroke, in per cent of the radius</source>
        <translation>每个笔触偏离笔画至多这么远，以半径的百分比计</translation>
    </message>
    <message>
        <source>The random jitter&apos;s seed: the same seed paints the same stroke again</source>
        <translation>随机抖动的种子：相同的种子再次绘制相同的笔画</translation>
    </message>
    <message>
        <source>See&amp;d</source>
        <translation>种子(&amp;D)</translation>
    </message>
    <message>
        <source>Loaded</source>
        <translation>已载入</translation>
    </message>
    <message>
        <source>Load Brush Tip</source>
        <translation>载入笔尖</translation>
    </message>
    <message>
        <source>Images (*.png *.tif *.tiff);;All files (*)</source>
        <translation>图像 (*.png *.tif *.tiff);;所有文件 (*)</translation>
    </message>
</context>
<context>
    <name>ui::BrushToolBar</name>
    <message>
        <source>Brush colour</source>
        <translation>画笔颜色</translation>
    </message>
    <message>
        <source>&amp;Radius</source>
        <translation>半径(&amp;R)</translation>
    </message>
    <message>
        <source> px</source>
        <translation> 像素</translation>
    </message>
    <message>
        <source>&amp;Hardness</source>
        <translation>硬度(&amp;H)</translation>
    </message>
    <message>
        <source> %</source>
        <translation>%</translation>
    </message>
    <message>
        <source>O&amp;pacity</source>
        <translation>不透明度(&amp;P)</translation>
    </message>
    <message>
        <source>The most one stroke covers</source>
        <translation>一笔最多能覆盖的程度</translation>
    </message>
    <message>
        <source>Paint &amp;into</source>
        <translation>绘制到(&amp;I)</translation>
    </message>
    <message>
        <source>Where paint goes: a texture (meshes with UVs) or vertex colours. Changing it starts the painting afresh.</source>
        <translation>颜料绘制的位置：纹理（带 UV 的网格）或顶点颜色。更改后将重新开始绘画。</translation>
    </message>
    <message>
        <source>Vertex colours</source>
        <translation>顶点颜色</translation>
    </message>
    <message>
        <source>Brush Colour</source>
        <translation>画笔颜色</translation>
    </message>
    <message>
        <source>Brush radius on screen ([ smaller, ] larger)</source>
        <translation>画笔在屏幕上的半径（[ 缩小，] 放大）</translation>
    </message>
    <message>
        <source>0: soft falloff from the centre, 100: a hard edge (Shift+[ softer, Shift+] harder)</source>
        <translation>0：从中心柔和衰减，100：硬边（Shift+[ 更软，Shift+] 更硬）</translation>
    </message>
    <message>
        <source>Brush Bar</source>
        <translation>画笔栏</translation>
    </message>
    <message>
        <source>This model has no texture coordinates (UVs): a texture gets an automatic UV layout; vertex colours follow its vertices.</source>
        <translation>此模型没有纹理坐标（UV）：纹理会获得自动 UV 布局；顶点颜色取决于其顶点。</translation>
    </message>
    <message>
        <source>Texture %1 × %1, automatic UVs</source>
        <translation>纹理 %1 × %1，自动 UV</translation>
    </message>
    <message>
        <source>Texture %1</source>
        <translation>纹理 %1</translation>
    </message>
    <message>
        <source>Texture %1, automatic UVs</source>
        <translation>纹理 %1，自动 UV</translation>
    </message>
    <message>
        <source>A new texture of %1 × %1 texels over an automatic UV layout: places that share UVs are painted apart.</source>
        <translation>一张 %1 × %1 纹素的新纹理，使用自动 UV 布局：共用 UV 的位置会被分开绘制。</translation>
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
        <translation>材质 %1</translation>
    </message>
    <message>
        <source>%1: %2 (its base colour texture)</source>
        <translation>%1：%2（其基础颜色纹理）</translation>
    </message>
    <message>
        <source>%1: %2 (a new texture)</source>
        <translation>%1：%2（新纹理）</translation>
    </message>
    <message>
        <source>Painted into:</source>
        <translation>绘制到：</translation>
    </message>
    <message numerus="yes">
        <source>… and %n more material(s)</source>
        <translation>
            <numerusform>……以及另外 %n 个材质</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ui::ColorPanel</name>
    <message>
        <source>Foreground colour: the brush paints with it</source>
        <translation>前景色：画笔使用此颜色绘画</translation>
    </message>
    <message>
        <source>Foreground Colour</source>
        <translation>前景色</translation>
    </message>
    <message>
        <source>Background colour (X swaps it with the foreground)</source>
        <translation>背景色（按 X 与前景色互换）</translation>
    </message>
    <message>
        <source>Swap foreground and background colours (X)</source>
        <translation>互换前景色和背景色 (X)</translation>
    </message>
    <message>
        <source>&amp;Hex</source>
        <translation>十六进制(&amp;H)</translation>
    </message>
    <message>
        <source>The foreground colour as #rrggbb (sRGB)</source>
        <translation>以 #rrggbb (sRGB) 表示的前景色</translation>
    </message>
    <message>
        <source>Recent colours</source>
        <translation>最近使用的颜色</translation>
    </message>
    <message>
        <source>Background Colour</source>
        <translation>背景色</translation>
    </message>
</context>
<context>
    <name>ui::DepthLayersBuilder</name>
    <message>
        <source>not enough memory for the depth layers of this view</source>
        <translation>内存不足，无法构建此视图的深度层</translation>
    </message>
    <message>
        <source>not enough memory for the symmetric views</source>
        <translation>内存不足，无法构建对称视图</translation>
    </message>
</context>
<context>
    <name>ui::DepthLayersPanel</name>
    <message>
        <source>The whole view, front to back</source>
        <translation>整个视图，由前到后</translation>
    </message>
    <message>
        <source>Depth layer %1
Fragments: %2
Regions: %3</source>
        <translation>深度层 %1
片元：%2
区域：%3</translation>
    </message>
    <message>
        <source>Show depth layer %1 alone</source>
        <translation>单独显示深度层 %1</translation>
    </message>
    <message>
        <source>Depth layers appear when the view stays still.</source>
        <translation>视图静止后将显示深度层。</translation>
    </message>
    <message>
        <source>Click a depth layer to see it alone; “All depth layers” shows the whole view.</source>
        <translation>单击一个深度层可单独查看；“所有深度层”显示整个视图。</translation>
    </message>
    <message>
        <source>All depth layers
Depth layers: %1
Regions: %2</source>
        <translation>所有深度层
深度层：%1
区域：%2</translation>
    </message>
</context>
<context>
    <name>ui::FillPanel</name>
    <message>
        <source>Region under the cursor</source>
        <translation>光标下的区域</translation>
    </message>
    <message>
        <source>Connected surface</source>
        <translation>相连的表面</translation>
    </message>
    <message>
        <source>Similar colour</source>
        <translation>相近的颜色</translation>
    </message>
    <message>
        <source>The segmented region clicked in this view, including the part of it hidden behind other surfaces</source>
        <translation>在此视图中点击的分割区域，包括其被其他表面遮挡的部分</translation>
    </message>
    <message>
        <source>Everything connected to the clicked surface in the mesh, seen or not, from any side</source>
        <translation>网格中与所点击表面相连的一切，无论是否可见，无论从哪一侧</translation>
    </message>
    <message>
        <source>The surface around the clicked point whose colour is within the tolerance of the colour there</source>
        <translation>所点击位置周围颜色与该处颜色之差在容差之内的表面</translation>
    </message>
    <message>
        <source>What a click with the Fill tool fills</source>
        <translation>使用填充工具点击时填充的范围</translation>
    </message>
    <message>
        <source>Colour tolerance</source>
        <translation>颜色容差</translation>
    </message>
    <message>
        <source>How far a colour may differ from the clicked one and still be filled (in any channel): 0 % takes only the very same colour</source>
        <translation>颜色与所点击颜色（在任一通道上）相差多少仍会被填充：0% 只填充完全相同的颜色</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1%</translation>
    </message>
    <message>
        <source>&amp;Fill:</source>
        <translation>填充(&amp;F)：</translation>
    </message>
    <message>
        <source>&amp;Tolerance:</source>
        <translation>容差(&amp;T)：</translation>
    </message>
</context>
<context>
    <name>ui::HiddenRegionsPanel</name>
    <message>
        <source>Paint with the Hide tool (H) to hide regions and see behind them.</source>
        <translation>用隐藏工具 (H) 涂抹，可隐藏区域并看到其后面的内容。</translation>
    </message>
    <message>
        <source>&amp;Unhide</source>
        <translation>取消隐藏(&amp;U)</translation>
    </message>
    <message>
        <source>Show the selected regions again</source>
        <translation>重新显示所选区域</translation>
    </message>
    <message>
        <source>Unhide &amp;All</source>
        <translation>全部取消隐藏(&amp;A)</translation>
    </message>
    <message numerus="yes">
        <source>Region %1 · depth layer %2 · %n pixel(s)</source>
        <translation>
            <numerusform>区域 %1 · 深度层 %2 · %n 个像素</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ui::HistoryBridge</name>
    <message>
        <source>Paint Stroke</source>
        <translation>画笔笔画</translation>
    </message>
    <message>
        <source>Fill</source>
        <translation>填充</translation>
    </message>
    <message>
        <source>Pop Up Region</source>
        <translation>弹出区域</translation>
    </message>
    <message>
        <source>Hide Regions</source>
        <translation>隐藏区域</translation>
    </message>
    <message>
        <source>Unhide Regions</source>
        <translation>取消隐藏区域</translation>
    </message>
    <message>
        <source>Reset Region Order</source>
        <translation>重置区域顺序</translation>
    </message>
    <message>
        <source>Change Paint Target</source>
        <translation>更改绘制目标</translation>
    </message>
    <message>
        <source>Run Script</source>
        <translation>运行脚本</translation>
    </message>
    <message>
        <source>Change Paint Layers</source>
        <translation>更改绘画层</translation>
    </message>
</context>
<context>
    <name>ui::HsvPicker</name>
    <message>
        <source>Saturation and value (square) and hue (bar)</source>
        <translation>饱和度和明度（方块）以及色相（色条）</translation>
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
        <translation>OpenGL 错误</translation>
    </message>
    <message>
        <source>The 3D view cannot be shown.</source>
        <translation>无法显示三维视图。</translation>
    </message>
    <message>
        <source>Could not build the depth layers: %1</source>
        <translation>无法构建深度层：%1</translation>
    </message>
    <message>
        <source>Trefoil knot</source>
        <translation>三叶结</translation>
    </message>
    <message>
        <source>Hexagonal ring</source>
        <translation>六边形环</translation>
    </message>
    <message>
        <source>Row of four</source>
        <translation>四个一排</translation>
    </message>
    <message>
        <source>Torus knot (1M triangles)</source>
        <translation>环面纽结（100 万个三角形）</translation>
    </message>
    <message>
        <source>Torus knot (%1 triangles)</source>
        <translation>环面纽结（%1 个三角形）</translation>
    </message>
    <message>
        <source>Segmentation</source>
        <translation>分割</translation>
    </message>
    <message>
        <source>Region Graph</source>
        <translation>区域图</translation>
    </message>
    <message>
        <source>&amp;Shaded</source>
        <translation>着色(&amp;S)</translation>
    </message>
    <message>
        <source>Show the model shaded, all depth layers</source>
        <translation>以着色方式显示模型的所有深度层</translation>
    </message>
    <message>
        <source>Single Depth &amp;Layer</source>
        <translation>单个深度层(&amp;L)</translation>
    </message>
    <message>
        <source>Se&amp;gmentation Map</source>
        <translation>分割图(&amp;G)</translation>
    </message>
    <message>
        <source>Colour every region of the visible depth layer differently</source>
        <translation>用不同颜色显示可见深度层的每个区域</translation>
    </message>
    <message>
        <source>Region &amp;Boundaries</source>
        <translation>区域边界(&amp;B)</translation>
    </message>
    <message>
        <source>Outline where a surface is not connected to its neighbours on the same depth layer</source>
        <translation>勾勒出表面与同一深度层上相邻部分不相连的地方</translation>
    </message>
    <message>
        <source>Building depth layers…</source>
        <translation>正在构建深度层…</translation>
    </message>
    <message>
        <source>build_layers of this view:
capture %1 ms (drawing), %2 ms (sorting)
connectivity %3 ms, regions %4 ms
%5 ms from the capture to the picture</source>
        <translation>此视图的 build_layers：
捕获 %1 毫秒（绘制），%2 毫秒（排序）
连通性 %3 毫秒，区域 %4 毫秒
从捕获到画面 %5 毫秒</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>打开(&amp;O)…</translation>
    </message>
    <message>
        <source>New from &amp;Built-in</source>
        <translation>从内置模型新建(&amp;B)</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>最近打开(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <source>&amp;Frame All</source>
        <translation>全部显示(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;Orthographic</source>
        <translation>正交投影(&amp;O)</translation>
    </message>
    <message>
        <source>&amp;Panels</source>
        <translation>面板(&amp;P)</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <source>&amp;About LayerPaint</source>
        <translation>关于 LayerPaint(&amp;A)</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>关于 Qt(&amp;Q)</translation>
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
        <translation>没有最近打开的文件</translation>
    </message>
    <message>
        <source>&amp;Clear Menu</source>
        <translation>清除列表(&amp;C)</translation>
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
        <translation>所有文件 (*)</translation>
    </message>
    <message>
        <source>About LayerPaint</source>
        <translation>关于 LayerPaint</translation>
    </message>
    <message>
        <source>&lt;h3&gt;LayerPaint %1&lt;/h3&gt;&lt;p&gt;Layer-aware 3D painting: paint surfaces hidden behind others in one stroke.&lt;/p&gt;&lt;p&gt;License: GNU GPL version 3 or later.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;LayerPaint %1&lt;/h3&gt;&lt;p&gt;图层感知的三维绘画：一笔画到被其他表面遮挡的表面上。&lt;/p&gt;&lt;p&gt;许可证：GNU GPL 第 3 版或更高版本。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Could not open %1</source>
        <translation>无法打开 %1</translation>
    </message>
    <message>
        <source>Open Failed</source>
        <translation>打开失败</translation>
    </message>
    <message>
        <source>Could not open “%1”.</source>
        <translation>无法打开“%1”。</translation>
    </message>
    <message>
        <source>Opening %1 cancelled</source>
        <translation>已取消打开 %1</translation>
    </message>
    <message>
        <source>Opening %1…</source>
        <translation>正在打开 %1…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Opening Model</source>
        <translation>正在打开模型</translation>
    </message>
    <message>
        <source>%1 — %2 vertices, %3 triangles</source>
        <translation>%1 — %2 个顶点，%3 个三角形</translation>
    </message>
    <message>
        <source>&amp;Layer-Aware Painting</source>
        <translation>图层感知绘画(&amp;L)</translation>
    </message>
    <message>
        <source>Layer-aware painting (L): strokes follow a surface behind whatever covers it</source>
        <translation>图层感知绘画 (L)：笔画沿着表面延伸到遮挡它的物体后面</translation>
    </message>
    <message>
        <source>Paint across depth layers; off: only the front-most surface is paintable</source>
        <translation>跨深度图层绘画；关闭时只能在最前面的表面上绘画</translation>
    </message>
    <message>
        <source>Layer-aware painting</source>
        <translation>图层感知绘画</translation>
    </message>
    <message>
        <source>Conventional painting</source>
        <translation>常规绘画</translation>
    </message>
    <message>
        <source>Show &amp;Brush Maps</source>
        <translation>显示画笔映射图(&amp;M)</translation>
    </message>
    <message>
        <source>While painting, show the paintable (red) and trackable (blue) pixels around the brush</source>
        <translation>绘画时显示画笔周围可绘制（红色）和可跟踪（蓝色）的像素</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>撤销(&amp;U)</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>撤销 %1(&amp;U)</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>重做(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>重做 %1(&amp;R)</translation>
    </message>
    <message>
        <source>Cannot paint this model: %1</source>
        <translation>无法在此模型上绘画：%1</translation>
    </message>
    <message>
        <source>Cannot paint: %1</source>
        <translation>无法绘画：%1</translation>
    </message>
    <message>
        <source>Cannot paint into that target: %1</source>
        <translation>无法绘制到该目标：%1</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>编辑(&amp;E)</translation>
    </message>
    <message>
        <source>&amp;Paint</source>
        <translation>绘画(&amp;P)</translation>
    </message>
    <message>
        <source>compute shader</source>
        <translation>计算着色器</translation>
    </message>
    <message>
        <source>C++</source>
        <translation>C++</translation>
    </message>
    <message>
        <source>Fill</source>
        <translation>填充</translation>
    </message>
    <message>
        <source>Tools</source>
        <translation>工具</translation>
    </message>
    <message>
        <source>&amp;Brush</source>
        <translation>画笔(&amp;B)</translation>
    </message>
    <message>
        <source>&amp;Eraser</source>
        <translation>橡皮擦(&amp;E)</translation>
    </message>
    <message>
        <source>&amp;Fill</source>
        <translation>填充(&amp;F)</translation>
    </message>
    <message>
        <source>Flood fill with the brush colour</source>
        <translation>用画笔颜色进行填充</translation>
    </message>
    <message>
        <source>E&amp;yedropper</source>
        <translation>吸管(&amp;Y)</translation>
    </message>
    <message>
        <source>Pick the surface colour under the cursor (or Ctrl+click)</source>
        <translation>拾取光标下的表面颜色（或按住 Ctrl 点击）</translation>
    </message>
    <message>
        <source>Paint to &amp;Hide</source>
        <translation>涂抹隐藏(&amp;H)</translation>
    </message>
    <message>
        <source>Hide every region the brush touches, revealing what lies behind</source>
        <translation>隐藏画笔触及的每个区域，露出其后面的内容</translation>
    </message>
    <message>
        <source>&amp;Pop Up</source>
        <translation>弹出(&amp;P)</translation>
    </message>
    <message>
        <source>Cannot fill: %1</source>
        <translation>无法填充：%1</translation>
    </message>
    <message>
        <source>Filled in %1 ms</source>
        <translation>填充用时 %1 毫秒</translation>
    </message>
    <message>
        <source>Nothing to fill there</source>
        <translation>那里没有可填充的内容</translation>
    </message>
    <message>
        <source>Region %1 popped up</source>
        <translation>已弹出区域 %1</translation>
    </message>
    <message>
        <source>Paint to Hide</source>
        <translation>涂抹隐藏</translation>
    </message>
    <message>
        <source>Brush</source>
        <translation>画笔</translation>
    </message>
    <message>
        <source>Colour</source>
        <translation>颜色</translation>
    </message>
    <message>
        <source>Layer-aware</source>
        <translation>图层感知</translation>
    </message>
    <message>
        <source>S&amp;maller Brush</source>
        <translation>缩小画笔(&amp;M)</translation>
    </message>
    <message>
        <source>Make the brush smaller</source>
        <translation>缩小画笔</translation>
    </message>
    <message>
        <source>Make the brush larger</source>
        <translation>放大画笔</translation>
    </message>
    <message>
        <source>Lower the brush hardness</source>
        <translation>降低画笔硬度</translation>
    </message>
    <message>
        <source>Har&amp;der Brush</source>
        <translation>更硬的画笔(&amp;D)</translation>
    </message>
    <message>
        <source>Raise the brush hardness</source>
        <translation>提高画笔硬度</translation>
    </message>
    <message>
        <source>S&amp;wap Colours</source>
        <translation>互换颜色(&amp;W)</translation>
    </message>
    <message>
        <source>Swap the foreground and background colours (X)</source>
        <translation>互换前景色和背景色 (X)</translation>
    </message>
    <message>
        <source>Swap the foreground and background colours</source>
        <translation>互换前景色和背景色</translation>
    </message>
    <message>
        <source>No surface here to pick a colour from</source>
        <translation>此处没有可拾取颜色的表面</translation>
    </message>
    <message>
        <source>Picked %1</source>
        <translation>已拾取 %1</translation>
    </message>
    <message>
        <source>Brush %1 px · %2 % hard</source>
        <translation>画笔 %1 像素 · 硬度 %2 %</translation>
    </message>
    <message>
        <source>Brush radius and hardness ([ ] and Shift+[ ] change them)</source>
        <translation>画笔半径和硬度（[ ] 和 Shift+[ ] 可调整）</translation>
    </message>
    <message>
        <source>&amp;Preferences…</source>
        <translation>首选项(&amp;P)…</translation>
    </message>
    <message>
        <source>Lar&amp;ger Brush</source>
        <translation>放大画笔(&amp;G)</translation>
    </message>
    <message>
        <source>Sof&amp;ter Brush</source>
        <translation>更软的画笔(&amp;T)</translation>
    </message>
    <message>
        <source>Projects and 3D models (*.glb *.gltf *.obj *.ply *.stl *.off)</source>
        <translation>项目和三维模型 (*.glb *.gltf *.obj *.ply *.stl *.off)</translation>
    </message>
    <message>
        <source>LayerPaint projects (*.glb)</source>
        <translation>LayerPaint 项目 (*.glb)</translation>
    </message>
    <message>
        <source>Open Project or Model</source>
        <translation>打开项目或模型</translation>
    </message>
    <message>
        <source>%1[*] — LayerPaint</source>
        <translation>%1[*] — LayerPaint</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>保存(&amp;S)</translation>
    </message>
    <message>
        <source>Save the painting and its settings as a project (.glb)</source>
        <translation>将绘画及其设置保存为项目 (.glb)</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>另存为(&amp;A)…</translation>
    </message>
    <message>
        <source>Save the project under another name</source>
        <translation>以另一个名称保存项目</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>导出(&amp;X)</translation>
    </message>
    <message>
        <source>glTF &amp;Binary (.glb)…</source>
        <translation>glTF 二进制 (.glb)(&amp;B)…</translation>
    </message>
    <message>
        <source>Wavefront &amp;OBJ (.obj + .mtl + textures)…</source>
        <translation>Wavefront OBJ（.obj + .mtl + 纹理）(&amp;O)…</translation>
    </message>
    <message>
        <source>Stanford &amp;PLY with Vertex Colours…</source>
        <translation>带顶点颜色的 Stanford PLY(&amp;P)…</translation>
    </message>
    <message>
        <source>Paint Texture as P&amp;NG (8-bit)…</source>
        <translation>绘画纹理为 PNG（8 位）(&amp;N)…</translation>
    </message>
    <message>
        <source>Paint Texture as PNG (&amp;16-bit)…</source>
        <translation>绘画纹理为 PNG（16 位）(&amp;1)…</translation>
    </message>
    <message>
        <source>Paint Texture as &amp;TIFF…</source>
        <translation>绘画纹理为 TIFF(&amp;T)…</translation>
    </message>
    <message>
        <source>Paint Texture as Open&amp;EXR…</source>
        <translation>绘画纹理为 OpenEXR(&amp;E)…</translation>
    </message>
    <message>
        <source>Painting into a new target (Undo brings the previous one back)</source>
        <translation>正在绘制到新的绘制目标（撤销可恢复之前的目标）</translation>
    </message>
    <message>
        <source>“%1” has no texture coordinates (UVs), so it is painted with vertex colours: the paint&apos;s detail follows its vertices.</source>
        <translation>“%1”没有纹理坐标（UV），因此使用顶点颜色绘制：颜料的细节取决于其顶点。</translation>
    </message>
    <message>
        <source>Recovered the unsaved work on “%1” that was autosaved at %2. Save it to keep it.</source>
        <translation>已恢复“%1”中于 %2 自动保存的未保存工作。请保存以保留它。</translation>
    </message>
    <message>
        <source>Opening “%1” gave these warnings:</source>
        <translation>打开“%1”时出现以下警告：</translation>
    </message>
    <message>
        <source>Warnings while loading are shown above the view</source>
        <translation>加载时的警告显示在视图上方</translation>
    </message>
    <message>
        <source>“%1” has no texture coordinates (UVs). Its vertices are far apart for the brush, so it gets an automatic UV layout to paint into a texture.</source>
        <translation>“%1”没有纹理坐标（UV）。对画笔而言其顶点相距较远，因此为其生成自动 UV 布局，以便绘制到纹理中。</translation>
    </message>
    <message>
        <source>Making an automatic UV layout…</source>
        <translation>正在生成自动 UV 布局…</translation>
    </message>
    <message>
        <source>The automatic UV layout was cancelled; the paint target stays as it was</source>
        <translation>自动 UV 布局已取消；绘制目标保持不变</translation>
    </message>
    <message>
        <source>Cannot paint into a texture with an automatic UV layout: %1</source>
        <translation>无法绘制到带自动 UV 布局的纹理：%1</translation>
    </message>
    <message>
        <source>Painting into a texture with an automatic UV layout (Undo brings the previous target back)</source>
        <translation>正在绘制到带自动 UV 布局的纹理（撤销可恢复之前的目标）</translation>
    </message>
    <message>
        <source>Painting into a texture with an automatic UV layout</source>
        <translation>正在绘制到带自动 UV 布局的纹理</translation>
    </message>
    <message>
        <source>Use Vertex Colours Instead</source>
        <translation>改用顶点颜色</translation>
    </message>
    <message>
        <source>Paint into a Texture (Automatic UV Layout)</source>
        <translation>绘制到纹理（自动 UV 布局）</translation>
    </message>
    <message>
        <source>Depth Layers</source>
        <translation>深度层</translation>
    </message>
    <message>
        <source>Show one depth layer alone (choose it in the Depth Layers panel)</source>
        <translation>单独显示一个深度层（在“深度层”面板中选择）</translation>
    </message>
    <message>
        <source>Depth layers: %1 · Fragments: %2 · Regions: %3 · Built in %4 ms</source>
        <translation>深度层：%1 · 片元：%2 · 区域：%3 · 构建耗时 %4 毫秒</translation>
    </message>
    <message>
        <source>Paint Layers</source>
        <translation>绘画层</translation>
    </message>
    <message>
        <source>Paint &amp;Layers</source>
        <translation>绘画层(&amp;L)</translation>
    </message>
    <message>
        <source>Vertex colours hold base colour only: roughness and metallic need a texture as the paint target.</source>
        <translation>顶点颜色只包含基础颜色：粗糙度和金属度需要以纹理作为绘画目标。</translation>
    </message>
    <message>
        <source>Paint strokes with the brush; Shift+click draws a straight line on from the last stroke</source>
        <translation>用画笔画出笔画；按住 Shift 点击从上一笔的末端画一条直线</translation>
    </message>
    <message>
        <source>Erase paint back to the model&apos;s original colours; Shift+click erases along a straight line from the last stroke</source>
        <translation>擦除颜料，恢复模型原来的颜色；按住 Shift 点击沿从上一笔起的直线擦除</translation>
    </message>
    <message>
        <source>Bring the region below the visible one to the front (or Ctrl+Shift+click); click again to cycle</source>
        <translation>将可见区域下面的区域提到最前（或按住 Ctrl+Shift 点击）；再次点击可依次切换</translation>
    </message>
    <message>
        <source>Straight line from the end of the last stroke</source>
        <translation>从上一笔末端画出的直线</translation>
    </message>
    <message>
        <source>No stroke to go on from: a dot here; the next Shift+click draws a line from it</source>
        <translation>没有可接续的笔画：此处画一个点；下一次按住 Shift 点击将从这里画线</translation>
    </message>
    <message>
        <source>Stroke Stabili&amp;zer</source>
        <translation>笔画稳定器(&amp;Z)</translation>
    </message>
    <message>
        <source>Strokes follow the pointer on a string, smoothing out wobbles (length and smoothing in the Brush panel)</source>
        <translation>笔画用一根绳子跟随指针，消除抖动（长度和平滑在画笔面板中设置）</translation>
    </message>
    <message>
        <source>&amp;Channel</source>
        <translation>通道(&amp;C)</translation>
    </message>
    <message>
        <source>&amp;Material</source>
        <translation>材质(&amp;M)</translation>
    </message>
    <message>
        <source>Show the paint lit as a metallic-roughness material</source>
        <translation>将绘制结果显示为受光照的金属度-粗糙度材质</translation>
    </message>
    <message>
        <source>&amp;Base Colour</source>
        <translation>基础色(&amp;B)</translation>
    </message>
    <message>
        <source>Show the base colour alone, unlit</source>
        <translation>仅显示基础色，不受光照</translation>
    </message>
    <message>
        <source>&amp;Roughness</source>
        <translation>粗糙度(&amp;R)</translation>
    </message>
    <message>
        <source>Show roughness as grey: black smooth, white rough</source>
        <translation>以灰度显示粗糙度：黑色光滑，白色粗糙</translation>
    </message>
    <message>
        <source>M&amp;etallic</source>
        <translation>金属度(&amp;E)</translation>
    </message>
    <message>
        <source>Show metallic as grey: black non-metal, white metal</source>
        <translation>以灰度显示金属度：黑色非金属，白色金属</translation>
    </message>
    <message>
        <source>Brush Presets</source>
        <translation>画笔预设</translation>
    </message>
    <message>
        <source>Brush preset: %1</source>
        <translation>画笔预设：%1</translation>
    </message>
    <message>
        <source>One page on layer-aware painting, pop-up, paint to hide, orbiting and the keys</source>
        <translation>一页介绍分层感知绘画、弹出、绘制隐藏、环绕和快捷键</translation>
    </message>
    <message>
        <source>Quick &amp;Guide</source>
        <translation>快速指南(&amp;G)</translation>
    </message>
    <message>
        <source>Building the symmetric views… %1 %</source>
        <translation>正在构建对称视图… %1 %</translation>
    </message>
    <message>
        <source>Waiting for the symmetric views before painting…</source>
        <translation>正在等待对称视图，之后开始绘制…</translation>
    </message>
    <message>
        <source>The symmetric views could not be built: this stroke paints without its copies</source>
        <translation>无法构建对称视图：此笔画将不绘制其对称副本</translation>
    </message>
    <message>
        <source>S&amp;ymmetry</source>
        <translation>对称(&amp;Y)</translation>
    </message>
    <message>
        <source>Mirror &amp;X</source>
        <translation>镜像 X(&amp;X)</translation>
    </message>
    <message>
        <source>Mirror &amp;Y</source>
        <translation>镜像 Y(&amp;Y)</translation>
    </message>
    <message>
        <source>Mirror &amp;Z</source>
        <translation>镜像 Z(&amp;Z)</translation>
    </message>
    <message>
        <source>Repeat every dab mirrored across the model&apos;s plane across this axis, also where that side is hidden or faces away</source>
        <translation>沿模型垂直于此轴的平面镜像重复每个笔触，即使那一面被遮挡或背向相机</translation>
    </message>
    <message>
        <source>Symmetry &amp;Off</source>
        <translation>关闭对称(&amp;O)</translation>
    </message>
    <message>
        <source>No mirrored or radial copies of the dabs</source>
        <translation>笔触不做镜像或径向复制</translation>
    </message>
    <message>
        <source>Symmetry &amp;Settings…</source>
        <translation>对称设置(&amp;S)…</translation>
    </message>
    <message>
        <source>Show the Brush panel&apos;s symmetry settings: the centre and radial copies</source>
        <translation>显示画笔面板的对称设置：中心和径向副本</translation>
    </message>
    <message>
        <source>Symmetry: every dab repeated on the mirrored surface, also where it is hidden (radial copies in the Brush panel)</source>
        <translation>对称：每个笔触都在镜像表面上重复，即使该处被遮挡（径向副本在画笔面板中设置）</translation>
    </message>
    <message>
        <source>%1× radial</source>
        <translation>%1× 径向</translation>
    </message>
    <message>
        <source>Symmetry: off</source>
        <translation>对称：关</translation>
    </message>
    <message>
        <source>Symmetry: %1</source>
        <translation>对称：%1</translation>
    </message>
    <message>
        <source>&amp;Raise Texture Size…</source>
        <translation>增大纹理尺寸(&amp;R)…</translation>
    </message>
    <message>
        <source>A texture&apos;s size can be raised while painting into a texture (Paint into, on the brush bar)</source>
        <translation>绘制到纹理时才能增大纹理尺寸（画笔栏上的“绘制到”）</translation>
    </message>
    <message>
        <source>material %1</source>
        <translation>材质 %1</translation>
    </message>
    <message>
        <source>%1. %2 (%3 × %4)</source>
        <translation>%1. %2（%3 × %4）</translation>
    </message>
    <message>
        <source>Raise Texture Size</source>
        <translation>增大纹理尺寸</translation>
    </message>
    <message>
        <source>The material whose texture gets larger:</source>
        <translation>要增大其纹理的材质：</translation>
    </message>
    <message>
        <source>%1 × %2</source>
        <translation>%1 × %2</translation>
    </message>
    <message>
        <source>That texture is as large as a texture can be (8192 texels on a side)</source>
        <translation>该纹理已是最大尺寸（每边 8192 纹素）</translation>
    </message>
    <message>
        <source>New size (now %1 × %2; what is painted is resampled):</source>
        <translation>新尺寸（当前 %1 × %2；已绘制的内容会被重新采样）：</translation>
    </message>
    <message>
        <source>Cannot raise the texture size: %1</source>
        <translation>无法增大纹理尺寸：%1</translation>
    </message>
    <message>
        <source>The texture is %1 now (Undo brings the previous size back)</source>
        <translation>纹理现在为 %1（撤销可恢复之前的尺寸）</translation>
    </message>
    <message>
        <source>A Fill Layer Takes No Strokes</source>
        <translation>填充层不接受笔画</translation>
    </message>
    <message>
        <source>“%1” is a fill layer: its values are the same everywhere. Paint its mask to shape where it shows, or paint on a paint layer above it.</source>
        <translation>“%1”是填充层：其数值处处相同。绘制它的遮罩来决定它显示的位置，或在它上方的绘画层上绘制。</translation>
    </message>
    <message>
        <source>Paint Its Mask</source>
        <translation>绘制其遮罩</translation>
    </message>
    <message>
        <source>Add a Mask and Paint It</source>
        <translation>添加遮罩并绘制</translation>
    </message>
    <message>
        <source>Add a Paint Layer Above</source>
        <translation>在上方添加绘画层</translation>
    </message>
    <message>
        <source>Painting the mask of “%1”</source>
        <translation>正在绘制“%1”的遮罩</translation>
    </message>
    <message>
        <source>Painting “%1”</source>
        <translation>正在绘制“%1”</translation>
    </message>
    <message>
        <source>Strokes paint the mask: black hides the paint layer, white shows it</source>
        <translation>笔画绘制遮罩：黑色隐藏绘画层，白色显示绘画层</translation>
    </message>
    <message>
        <source>Strokes paint this paint layer</source>
        <translation>笔画绘制此绘画层</translation>
    </message>
    <message>
        <source>Export &amp;Textures…</source>
        <translation>导出纹理(&amp;T)…</translation>
    </message>
    <message>
        <source>Write each texture set&apos;s maps for a game engine or another tool, through an export preset</source>
        <translation>通过导出预设，为游戏引擎或其他工具写出每个纹理集的贴图</translation>
    </message>
    <message>
        <source>The mask alone: black hides, white shows. Alt+click it again to see the paint layers.</source>
        <translation>仅显示蒙版：黑色隐藏，白色显示。再次 Alt+单击它可重新查看绘画层。</translation>
    </message>
    <message>
        <source>The paint layers again</source>
        <translation>重新显示绘画层</translation>
    </message>
</context>
<context>
    <name>ui::MessageBar</name>
    <message>
        <source>Dismiss</source>
        <translation>关闭</translation>
    </message>
    <message numerus="yes">
        <source>… and %n more (see the tooltip)</source>
        <translation>
            <numerusform>……还有 %n 条（见工具提示）</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ui::PaintLayersPanel</name>
    <message>
        <source>Normal</source>
        <translation>正常</translation>
    </message>
    <message>
        <source>Multiply</source>
        <translation>正片叠底</translation>
    </message>
    <message>
        <source>Screen</source>
        <translation>滤色</translation>
    </message>
    <message>
        <source>Overlay</source>
        <translation>叠加</translation>
    </message>
    <message>
        <source>Soft Light</source>
        <translation>柔光</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>相加</translation>
    </message>
    <message>
        <source>Subtract</source>
        <translation>减去</translation>
    </message>
    <message>
        <source>Darken</source>
        <translation>变暗</translation>
    </message>
    <message>
        <source>Lighten</source>
        <translation>变亮</translation>
    </message>
    <message>
        <source>Difference</source>
        <translation>差值</translation>
    </message>
    <message>
        <source>The paint layers, the uppermost on top. Click a row to paint on it, its eye to show or hide it, its mask to paint the mask; double-click a name to rename it; drag rows to reorder them.</source>
        <translation>绘画层，最上层在顶部。单击一行以在其上绘画，单击眼睛以显示或隐藏，单击蒙版以绘制蒙版；双击名称可重命名；拖动行可调整顺序。</translation>
    </message>
    <message>
        <source>How much of the current paint layer shows</source>
        <translation>当前绘画层的显示程度</translation>
    </message>
    <message>
        <source>&amp;Opacity</source>
        <translation>不透明度(&amp;O)</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1%</translation>
    </message>
    <message>
        <source>How the current paint layer combines with what lies under it</source>
        <translation>当前绘画层与其下方内容的混合方式</translation>
    </message>
    <message>
        <source>&amp;Blend mode</source>
        <translation>混合模式(&amp;B)</translation>
    </message>
    <message>
        <source>Lock &amp;transparency</source>
        <translation>锁定透明度(&amp;T)</translation>
    </message>
    <message>
        <source>Painting changes the colour of what is on the paint layer, never where it is or how much</source>
        <translation>绘画只改变绘画层上已有内容的颜色，不改变其位置或多少</translation>
    </message>
    <message>
        <source>&amp;New Paint Layer</source>
        <translation>新建绘画层(&amp;N)</translation>
    </message>
    <message>
        <source>New</source>
        <translation>新建</translation>
    </message>
    <message>
        <source>Add a paint layer above the current one</source>
        <translation>在当前层之上添加一个绘画层</translation>
    </message>
    <message>
        <source>New F&amp;ill Layer</source>
        <translation>新建填充层(&amp;I)</translation>
    </message>
    <message>
        <source>Fill</source>
        <translation>填充</translation>
    </message>
    <message>
        <source>Add a paint layer of uniform channel values (the brush&apos;s) above the current one</source>
        <translation>在当前绘画层之上添加一个统一通道值（画笔的值）的绘画层</translation>
    </message>
    <message>
        <source>&amp;Duplicate Paint Layer</source>
        <translation>复制绘画层(&amp;D)</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>复制</translation>
    </message>
    <message>
        <source>Copy the current paint layer</source>
        <translation>复制当前绘画层</translation>
    </message>
    <message>
        <source>D&amp;elete Paint Layer</source>
        <translation>删除绘画层(&amp;E)</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>删除</translation>
    </message>
    <message>
        <source>Delete the current paint layer</source>
        <translation>删除当前绘画层</translation>
    </message>
    <message>
        <source>&amp;Merge Down</source>
        <translation>向下合并(&amp;M)</translation>
    </message>
    <message>
        <source>Merge</source>
        <translation>合并</translation>
    </message>
    <message>
        <source>Merge the current paint layer into the one below</source>
        <translation>将当前绘画层合并到下方的层</translation>
    </message>
    <message>
        <source>&amp;Flatten Paint Layers</source>
        <translation>拼合绘画层(&amp;F)</translation>
    </message>
    <message>
        <source>Flatten</source>
        <translation>拼合</translation>
    </message>
    <message>
        <source>Merge every visible paint layer into one</source>
        <translation>将所有可见绘画层合并为一层</translation>
    </message>
    <message>
        <source>Flattened</source>
        <translation>已拼合</translation>
    </message>
    <message>
        <source>Add M&amp;ask</source>
        <translation>添加蒙版(&amp;A)</translation>
    </message>
    <message>
        <source>Mask</source>
        <translation>蒙版</translation>
    </message>
    <message>
        <source>Give the current paint layer a mask (black hides, white shows)</source>
        <translation>为当前绘画层添加蒙版（黑色隐藏，白色显示）</translation>
    </message>
    <message>
        <source>Delete Mas&amp;k</source>
        <translation>删除蒙版(&amp;K)</translation>
    </message>
    <message>
        <source>No Mask</source>
        <translation>无蒙版</translation>
    </message>
    <message>
        <source>Remove the current paint layer&apos;s mask</source>
        <translation>移除当前绘画层的蒙版</translation>
    </message>
    <message>
        <source>&amp;Rename…</source>
        <translation>重命名(&amp;R)…</translation>
    </message>
    <message>
        <source>Open a model to paint in paint layers.</source>
        <translation>打开一个模型以在绘画层中绘画。</translation>
    </message>
    <message>
        <source>Vertex colours have no paint layers: choose a texture as the paint target (in the brush bar) to paint in paint layers.</source>
        <translation>顶点颜色没有绘画层：请（在画笔栏中）选择纹理作为绘画目标，以在绘画层中绘画。</translation>
    </message>
    <message>
        <source>Shown: click to hide</source>
        <translation>显示中：单击以隐藏</translation>
    </message>
    <message>
        <source>Hidden: click to show</source>
        <translation>已隐藏：单击以显示</translation>
    </message>
    <message>
        <source>fill layer</source>
        <translation>填充层</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <source>, </source>
        <translation>，</translation>
    </message>
    <message>
        <source>Base</source>
        <translation>基础</translation>
    </message>
    <message>
        <source>The model&apos;s own surface (painting here changes it directly)</source>
        <translation>模型自身的表面（在此绘画会直接改变它）</translation>
    </message>
    <message>
        <source>Paint layers: %1</source>
        <translation>绘画层：%1</translation>
    </message>
    <message>
        <source>Fill %1</source>
        <translation>填充 %1</translation>
    </message>
    <message>
        <source>Paint Layer %1</source>
        <translation>绘画层 %1</translation>
    </message>
    <message>
        <source>Whether the fill layer sets the base colour</source>
        <translation>填充层是否设置基础颜色</translation>
    </message>
    <message>
        <source>The fill layer&apos;s base colour (click to choose)</source>
        <translation>填充层的基础颜色（点击选择）</translation>
    </message>
    <message>
        <source>&amp;Fill colour</source>
        <translation>填充颜色(&amp;F)</translation>
    </message>
    <message>
        <source>Fill Layer Colour</source>
        <translation>填充层颜色</translation>
    </message>
    <message>
        <source>&amp;Roughness</source>
        <translation>粗糙度(&amp;R)</translation>
    </message>
    <message>
        <source>The roughness the fill layer sets; Off leaves roughness alone</source>
        <translation>填充层设置的粗糙度；关闭则不改变粗糙度</translation>
    </message>
    <message>
        <source>&amp;Metallic</source>
        <translation>金属度(&amp;M)</translation>
    </message>
    <message>
        <source>How metallic the fill layer makes the surface; Off leaves metallic alone</source>
        <translation>填充层使表面有多金属；关闭则不改变金属度</translation>
    </message>
    <message>
        <source>Texture set:</source>
        <translation>纹理集：</translation>
    </message>
    <message>
        <source>Each texture the model paints into, with the materials on it, is a texture set. The thumbnails show the chosen one&apos;s paint; strokes paint every texture set they cross.</source>
        <translation>模型绘制的每张纹理及其上的材质构成一个纹理集。缩略图显示所选纹理集的绘制内容；笔画会绘制它经过的每个纹理集。</translation>
    </message>
    <message>
        <source>Texture set %1</source>
        <translation>纹理集 %1</translation>
    </message>
    <message>
        <source>%1 (%2 × %3)</source>
        <translation>%1（%2 × %3）</translation>
    </message>
    <message>
        <source>Shown alone in the view: Alt+click to see the paint layers again</source>
        <translation>在视图中单独显示：Alt+单击可重新查看绘画层</translation>
    </message>
    <message>
        <source>Painting the mask (black hides, white shows); Alt+click shows it alone</source>
        <translation>正在绘制蒙版（黑色隐藏，白色显示）；Alt+单击可单独显示它</translation>
    </message>
    <message>
        <source>Mask: click to paint it, Alt+click to see it alone</source>
        <translation>蒙版：单击以绘制，Alt+单击以单独查看</translation>
    </message>
</context>
<context>
    <name>ui::PaintTargetJob</name>
    <message>
        <source>Making an automatic UV layout for “%1”…</source>
        <translation>正在为“%1”生成自动 UV 布局…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Automatic UV Layout</source>
        <translation>自动 UV 布局</translation>
    </message>
</context>
<context>
    <name>ui::PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation>首选项</translation>
    </message>
    <message>
        <source> MiB</source>
        <translation> MiB</translation>
    </message>
    <message>
        <source>The most memory undo keeps; the oldest strokes are forgotten beyond it</source>
        <translation>撤销最多占用的内存；超出时最早的笔画将被舍弃</translation>
    </message>
    <message>
        <source>&amp;Undo memory:</source>
        <translation>撤销内存(&amp;U)：</translation>
    </message>
    <message>
        <source>%1 × %1</source>
        <translation>%1 × %1</translation>
    </message>
    <message>
        <source>The size of a new texture for models without one to paint (used from the next model on)</source>
        <translation>没有可绘制纹理的模型所使用的新纹理大小（从下一个模型开始生效）</translation>
    </message>
    <message>
        <source>New &amp;texture size:</source>
        <translation>新纹理大小(&amp;T)：</translation>
    </message>
    <message>
        <source>Pen pressure curve (pressure to the power of this): below 1 a light touch gives more, above 1 it takes a firm press</source>
        <translation>笔压曲线（压力的该值次幂）：小于 1 时轻触效果更强，大于 1 时需要用力按压</translation>
    </message>
    <message>
        <source>&amp;Pressure curve:</source>
        <translation>压力曲线(&amp;P)：</translation>
    </message>
    <message>
        <source>Both: the middle button and Alt with any button</source>
        <translation>两者：中键以及 Alt 加任意键</translation>
    </message>
    <message>
        <source>Blender-like: middle drag orbits, Shift+middle pans</source>
        <translation>类似 Blender：中键拖动旋转，Shift+中键平移</translation>
    </message>
    <message>
        <source>Alt-based: Alt+left orbits, Alt+middle pans, Alt+right zooms</source>
        <translation>基于 Alt：Alt+左键旋转，Alt+中键平移，Alt+右键缩放</translation>
    </message>
    <message>
        <source>Which buttons move the camera; the wheel always zooms</source>
        <translation>哪些按键移动相机；滚轮始终用于缩放</translation>
    </message>
    <message>
        <source>&amp;Camera buttons:</source>
        <translation>相机按键(&amp;C)：</translation>
    </message>
    <message>
        <source>System</source>
        <translation>系统</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>语言(&amp;L)：</translation>
    </message>
    <message>
        <source>A new language applies after a restart.</source>
        <translation>新的语言将在重新启动后生效。</translation>
    </message>
    <message>
        <source> min</source>
        <translation> 分钟</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>How often a recovery copy of the work is saved; 0 turns it off</source>
        <translation>保存工作恢复副本的频率；0 表示关闭</translation>
    </message>
    <message>
        <source>&amp;Autosave every:</source>
        <translation>自动保存间隔(&amp;A)：</translation>
    </message>
</context>
<context>
    <name>ui::PressureCurveView</name>
    <message>
        <source>Pen pressure (right) to stroke pressure (up)</source>
        <translation>笔压（向右）到笔画压力（向上）</translation>
    </message>
</context>
<context>
    <name>ui::ProjectController</name>
    <message>
        <source>Autosaved</source>
        <translation>已自动保存</translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation>自动保存失败：%1</translation>
    </message>
    <message>
        <source>There is no model to save.</source>
        <translation>没有可保存的模型。</translation>
    </message>
    <message>
        <source>Save Project</source>
        <translation>保存项目</translation>
    </message>
    <message>
        <source>LayerPaint projects (*.glb)</source>
        <translation>LayerPaint 项目 (*.glb)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>所有文件 (*)</translation>
    </message>
    <message>
        <source>Still busy with the last save or export</source>
        <translation>仍在进行上一次保存或导出</translation>
    </message>
    <message>
        <source>Save Failed</source>
        <translation>保存失败</translation>
    </message>
    <message>
        <source>Could not save.</source>
        <translation>无法保存。</translation>
    </message>
    <message>
        <source>Saving %1…</source>
        <translation>正在保存 %1…</translation>
    </message>
    <message>
        <source>Saving cancelled; the file was not changed</source>
        <translation>保存已取消；文件未被更改</translation>
    </message>
    <message>
        <source>Could not save %1</source>
        <translation>无法保存 %1</translation>
    </message>
    <message>
        <source>Could not save “%1”. The file on disk was not changed.</source>
        <translation>无法保存“%1”。磁盘上的文件未被更改。</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>已保存 %1</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>未保存的更改</translation>
    </message>
    <message>
        <source>“%1” has unsaved changes.</source>
        <translation>“%1”有未保存的更改。</translation>
    </message>
    <message>
        <source>Do you want to save them?</source>
        <translation>是否保存这些更改？</translation>
    </message>
    <message>
        <source>glTF binary (*.glb)</source>
        <translation>glTF 二进制 (*.glb)</translation>
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
        <translation>PNG 图像 (*.png)</translation>
    </message>
    <message>
        <source>TIFF image (*.tif *.tiff)</source>
        <translation>TIFF 图像 (*.tif *.tiff)</translation>
    </message>
    <message>
        <source>OpenEXR image (*.exr)</source>
        <translation>OpenEXR 图像 (*.exr)</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>导出</translation>
    </message>
    <message>
        <source>The model is painted with vertex colours, so there is no paint texture: export it as glTF or PLY.</source>
        <translation>该模型使用顶点颜色绘画，因此没有绘画纹理：请导出为 glTF 或 PLY。</translation>
    </message>
    <message>
        <source>Export Failed</source>
        <translation>导出失败</translation>
    </message>
    <message>
        <source>Could not export the paint texture.</source>
        <translation>无法导出绘画纹理。</translation>
    </message>
    <message>
        <source>Exporting %1…</source>
        <translation>正在导出 %1…</translation>
    </message>
    <message>
        <source>Export cancelled</source>
        <translation>导出已取消</translation>
    </message>
    <message>
        <source>Could not export “%1”.</source>
        <translation>无法导出“%1”。</translation>
    </message>
    <message numerus="yes">
        <source>Exported %n file(s) to %1</source>
        <translation>
            <numerusform>已将 %n 个文件导出到 %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>LayerPaint</source>
        <translation>LayerPaint</translation>
    </message>
    <message>
        <source>an unsaved painting of %1</source>
        <translation>%1 的一幅未保存的绘画</translation>
    </message>
    <message>
        <source>Recover Unsaved Work</source>
        <translation>恢复未保存的工作</translation>
    </message>
    <message>
        <source>LayerPaint was not closed properly. Work on %1 was autosaved at %2.</source>
        <translation>LayerPaint 未正常关闭。%1 上的工作已于 %2 自动保存。</translation>
    </message>
    <message>
        <source>Recover it? It opens as an unsaved document.</source>
        <translation>要恢复吗？它将作为未保存的文档打开。</translation>
    </message>
    <message>
        <source>&amp;Recover</source>
        <translation>恢复(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Discard</source>
        <translation>丢弃(&amp;D)</translation>
    </message>
    <message>
        <source>&amp;Not Now</source>
        <translation>暂不(&amp;N)</translation>
    </message>
    <message>
        <source>“%1” is the open project. Exporting there would replace it with a plain model without its LayerPaint settings. Choose another name, or use File ▸ Save.</source>
        <translation>“%1”是当前打开的项目。导出到该文件会用不含 LayerPaint 设置的普通模型替换它。请选择其他名称，或使用“文件 ▸ 保存”。</translation>
    </message>
    <message>
        <source>Not exported: “%1” is the open project</source>
        <translation>未导出：“%1”是当前打开的项目</translation>
    </message>
    <message>
        <source>Export Refused</source>
        <translation>已拒绝导出</translation>
    </message>
    <message>
        <source>Could not export to “%1”.</source>
        <translation>无法导出到“%1”。</translation>
    </message>
    <message>
        <source>Also write each &amp;paint layer as images</source>
        <translation>同时将每个绘画层写为图像(&amp;P)</translation>
    </message>
    <message>
        <source>Beside the export, per paint layer: NAME_layer-N-LAYER_basecolor.png and its roughness, metallic and mask images, as the command line&apos;s --per-layer</source>
        <translation>在导出文件旁，每个绘画层写出 NAME_layer-N-LAYER_basecolor.png 及其粗糙度、金属度和蒙版图像，与命令行的 --per-layer 相同</translation>
    </message>
    <message>
        <source>The model has no paint layers</source>
        <translation>该模型没有绘画层</translation>
    </message>
    <message>
        <source>There are no paint layers to export (they need a paint texture).</source>
        <translation>没有可导出的绘画层（绘画层需要绘画纹理）。</translation>
    </message>
    <message>
        <source>Could not export the paint layers.</source>
        <translation>无法导出绘画层。</translation>
    </message>
    <message>
        <source>Not Everything Was Kept</source>
        <translation>未能保留全部内容</translation>
    </message>
    <message>
        <source>“%1” was written, but not all of the model could be kept:</source>
        <translation>已写入“%1”，但模型的部分内容未能保留：</translation>
    </message>
    <message>
        <source>Exporting textures to %1…</source>
        <translation>正在将纹理导出到 %1…</translation>
    </message>
</context>
<context>
    <name>ui::QuickGuideDialog</name>
    <message>
        <source>Quick Guide</source>
        <translation>快速指南</translation>
    </message>
    <message>
        <source>&lt;h2&gt;LayerPaint in one page&lt;/h2&gt;&lt;p&gt;LayerPaint splits the view into &lt;b&gt;depth layers&lt;/b&gt; (the first, second, … surface under each pixel) and regions, so you can paint surfaces that others hide. Turn &lt;i&gt;Layer-aware&lt;/i&gt; on with &lt;b&gt;L&lt;/b&gt; or the check box in the tool bar.&lt;/p&gt;</source>
        <translation>&lt;h2&gt;一页了解 LayerPaint&lt;/h2&gt;&lt;p&gt;LayerPaint 将视图分为&lt;b&gt;深度层&lt;/b&gt;（每个像素下的第一、第二……个表面）和区域，因此您可以绘制被其他表面遮挡的表面。用 &lt;b&gt;L&lt;/b&gt; 或工具栏中的复选框打开&lt;i&gt;分层感知&lt;/i&gt;。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Layer-aware stroke&lt;/h3&gt;&lt;p&gt;Drag with the brush (&lt;b&gt;B&lt;/b&gt;). With layer-aware painting on, the stroke stays on the surface it started on, also where it goes behind another one. Shift+click draws a straight line on from the end of the last stroke.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;分层感知笔画&lt;/h3&gt;&lt;p&gt;用画笔（&lt;b&gt;B&lt;/b&gt;）拖动。打开分层感知绘画后，笔画会停留在起始的表面上，即使经过其他表面的后方。Shift+单击从上一笔的末端画出直线。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Pop-up&lt;/h3&gt;&lt;p&gt;&lt;b&gt;Ctrl+Shift+click&lt;/b&gt; with any tool, or a click with the Pop Up tool (&lt;b&gt;P&lt;/b&gt;), brings the region under the visible one to the front. Click the same spot again to go deeper; after the last it starts from the top. &lt;b&gt;R&lt;/b&gt; resets the order.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;弹出&lt;/h3&gt;&lt;p&gt;任何工具下 &lt;b&gt;Ctrl+Shift+单击&lt;/b&gt;，或用弹出工具（&lt;b&gt;P&lt;/b&gt;）单击，将可见区域下方的区域移到最前。在同一位置再次单击则更深入；到最后一层后从顶部重新开始。&lt;b&gt;R&lt;/b&gt; 重置顺序。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Paint to hide&lt;/h3&gt;&lt;p&gt;With the Paint to Hide tool (&lt;b&gt;H&lt;/b&gt;) paint over regions on the segmentation map: they are hidden and what lies behind shows. The Paint to Hide panel unhides them, &lt;b&gt;Shift+H&lt;/b&gt; all at once.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;绘制隐藏&lt;/h3&gt;&lt;p&gt;用绘制隐藏工具（&lt;b&gt;H&lt;/b&gt;）在分割图上的区域上绘制：这些区域被隐藏，显示出后面的内容。绘制隐藏面板可取消隐藏，&lt;b&gt;Shift+H&lt;/b&gt; 一次全部取消。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Orbit about a surface point&lt;/h3&gt;&lt;p&gt;With View ▸ Orbit About Surface Point on, an orbit (middle drag, or Alt+left drag) that starts on the model turns about that point, on whatever depth layer is shown there.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;围绕表面点环绕&lt;/h3&gt;&lt;p&gt;打开 视图 ▸ 围绕表面点环绕 后，从模型上开始的环绕（中键拖动或 Alt+左键拖动）会围绕该点旋转，无论该处显示的是哪个深度层。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Drawing…</source>
        <translation>正在绘制…</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Keys&lt;/h3&gt;&lt;table cellspacing=&quot;4&quot;&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;B&lt;/b&gt; / &lt;b&gt;E&lt;/b&gt; / &lt;b&gt;G&lt;/b&gt; / &lt;b&gt;I&lt;/b&gt;&lt;/td&gt;&lt;td&gt;brush, eraser, fill, eyedropper (Ctrl+click with any tool)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;H&lt;/b&gt; / &lt;b&gt;P&lt;/b&gt;&lt;/td&gt;&lt;td&gt;paint to hide, pop up&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;L&lt;/b&gt;&lt;/td&gt;&lt;td&gt;layer-aware painting on or off&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;[&lt;/b&gt; &lt;b&gt;]&lt;/b&gt; / Shift+&lt;b&gt;[&lt;/b&gt; &lt;b&gt;]&lt;/b&gt;&lt;/td&gt;&lt;td&gt;brush size / hardness&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;X&lt;/b&gt;&lt;/td&gt;&lt;td&gt;swap foreground and background colours&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;F&lt;/b&gt; / &lt;b&gt;O&lt;/b&gt;&lt;/td&gt;&lt;td&gt;frame the model / orthographic&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Middle drag, Shift+, Ctrl+, wheel&lt;/td&gt;&lt;td&gt;orbit, pan, zoom&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Alt+left / right / middle drag&lt;/td&gt;&lt;td&gt;orbit, zoom, pan (for tablets)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Ctrl+Z&lt;/b&gt; / &lt;b&gt;Ctrl+Shift+Z&lt;/b&gt;&lt;/td&gt;&lt;td&gt;undo / redo&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
        <translation>&lt;h3&gt;快捷键&lt;/h3&gt;&lt;table cellspacing=&quot;4&quot;&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;B&lt;/b&gt; / &lt;b&gt;E&lt;/b&gt; / &lt;b&gt;G&lt;/b&gt; / &lt;b&gt;I&lt;/b&gt;&lt;/td&gt;&lt;td&gt;画笔、橡皮擦、填充、吸管（任何工具下 Ctrl+单击）&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;H&lt;/b&gt; / &lt;b&gt;P&lt;/b&gt;&lt;/td&gt;&lt;td&gt;绘制隐藏、弹出&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;L&lt;/b&gt;&lt;/td&gt;&lt;td&gt;打开或关闭分层感知绘画&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;[&lt;/b&gt; &lt;b&gt;]&lt;/b&gt; / Shift+&lt;b&gt;[&lt;/b&gt; &lt;b&gt;]&lt;/b&gt;&lt;/td&gt;&lt;td&gt;画笔大小 / 硬度&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;X&lt;/b&gt;&lt;/td&gt;&lt;td&gt;交换前景色和背景色&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;F&lt;/b&gt; / &lt;b&gt;O&lt;/b&gt;&lt;/td&gt;&lt;td&gt;框选模型 / 正交&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;中键拖动、Shift+、Ctrl+、滚轮&lt;/td&gt;&lt;td&gt;环绕、平移、缩放&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Alt+左键 / 右键 / 中键拖动&lt;/td&gt;&lt;td&gt;环绕、缩放、平移（适用于数位板）&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Ctrl+Z&lt;/b&gt; / &lt;b&gt;Ctrl+Shift+Z&lt;/b&gt;&lt;/td&gt;&lt;td&gt;撤销 / 重做&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</translation>
    </message>
    <message>
        <source>&amp;Show at start</source>
        <translation>启动时显示(&amp;S)</translation>
    </message>
    <message>
        <source>(no picture)</source>
        <translation>（无图片）</translation>
    </message>
</context>
<context>
    <name>ui::RegionGraphPanel</name>
    <message>
        <source>No regions yet</source>
        <translation>尚无区域</translation>
    </message>
    <message>
        <source>No regions in this view</source>
        <translation>此视图中没有区域</translation>
    </message>
    <message>
        <source>Regions: %1, connections: %2</source>
        <translation>区域：%1，连接：%2</translation>
    </message>
    <message>
        <source>Small regions merged into grey nodes: %1</source>
        <translation>合并为灰色节点的小区域：%1</translation>
    </message>
    <message>
        <source>Depth layer %1</source>
        <translation>深度层 %1</translation>
    </message>
    <message>
        <source>%1 small regions of depth layer %2
%3 pixels together</source>
        <translation>深度层 %2 上的 %1 个小区域
共 %3 个像素</translation>
    </message>
    <message>
        <source>+%1</source>
        <translation>+%1</translation>
    </message>
    <message>
        <source>Region %1 on depth layer %2
%3 pixels
Connected regions: %4</source>
        <translation>区域 %1，位于深度层 %2
%3 个像素
相连区域：%4</translation>
    </message>
    <message>
        <source>%1 pixel links</source>
        <translation>%1 条像素连接</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>适应</translation>
    </message>
    <message>
        <source>Show the whole graph (F or Home in the graph). The wheel zooms, dragging the background pans.</source>
        <translation>显示整个图（在图中按 F 或 Home）。滚轮缩放，拖动背景平移。</translation>
    </message>
    <message>
        <source> px</source>
        <translation> 像素</translation>
    </message>
    <message>
        <source>All sizes</source>
        <translation>全部大小</translation>
    </message>
    <message>
        <source>Hide regions smaller than this many pixels</source>
        <translation>隐藏像素数少于此值的区域</translation>
    </message>
    <message>
        <source>&amp;Hide under:</source>
        <translation>隐藏小于(&amp;H):</translation>
    </message>
    <message>
        <source>&amp;Neighbours only</source>
        <translation>仅邻居(&amp;N)</translation>
    </message>
    <message>
        <source>Show only the selected region (click a node) and the regions connected to it</source>
        <translation>只显示所选区域（单击节点）及与其相连的区域</translation>
    </message>
    <message>
        <source>Click a node to see its neighbours only</source>
        <translation>单击节点以只查看其邻居</translation>
    </message>
    <message>
        <source>Shown: %1 (filtered out: %2), in grey nodes: %3</source>
        <translation>显示：%1（已过滤：%2），灰色节点中：%3</translation>
    </message>
</context>
<context>
    <name>ui::RegionTools</name>
    <message>
        <source>&amp;Automatic Pop-up</source>
        <translation>自动弹出(&amp;A)</translation>
    </message>
    <message>
        <source>While painting layer-aware, bring the surface under the brush to the front when it goes behind another</source>
        <translation>图层感知绘画时，画笔下的表面进入其他表面后方时将其提到最前</translation>
    </message>
    <message>
        <source>&amp;See-Through Pop-ups</source>
        <translation>半透明弹出区域(&amp;T)</translation>
    </message>
    <message>
        <source>Draw popped-up and revealed regions half transparent, so what surrounds them stays visible</source>
        <translation>以半透明方式绘制弹出和显露的区域，使其周围的内容仍然可见</translation>
    </message>
    <message>
        <source>Orbit About &amp;Surface Point</source>
        <translation>绕表面点旋转(&amp;R)</translation>
    </message>
    <message>
        <source>Start an orbit on the model to turn about that point, on whatever depth layer is shown there</source>
        <translation>在模型上开始旋转时将绕该点旋转，无论该处显示的是哪个深度层</translation>
    </message>
    <message>
        <source>&amp;Reset Region Order</source>
        <translation>重置区域顺序(&amp;R)</translation>
    </message>
    <message>
        <source>Show the regions in their original order (depth layer 1 in front)</source>
        <translation>按原始顺序显示区域（深度层 1 在最前）</translation>
    </message>
    <message>
        <source>Reset the region order (R)</source>
        <translation>重置区域顺序 (R)</translation>
    </message>
    <message>
        <source>U&amp;nhide All Regions</source>
        <translation>取消隐藏所有区域(&amp;N)</translation>
    </message>
    <message>
        <source>Show every hidden region again (Shift+H)</source>
        <translation>重新显示所有隐藏的区域 (Shift+H)</translation>
    </message>
    <message>
        <source>Nothing to pop up here</source>
        <translation>这里没有可弹出的区域</translation>
    </message>
    <message>
        <source>Region %1 (depth layer %2) in front; click again to go deeper</source>
        <translation>区域 %1（深度层 %2）已在最前；再次点击可继续深入</translation>
    </message>
    <message numerus="yes">
        <source>%n region(s) hidden</source>
        <translation>
            <numerusform>已隐藏 %n 个区域</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ui::ScriptActions</name>
    <message>
        <source>the script&apos;s view (%1×%2) is not the window&apos;s (%3×%4); replay it with layerpaint-cli</source>
        <translation>脚本的视图（%1×%2）与窗口的视图（%3×%4）不同；请用 layerpaint-cli 回放</translation>
    </message>
    <message>
        <source>the depth layers of this view cannot be built</source>
        <translation>无法构建此视图的深度层</translation>
    </message>
    <message>
        <source>Run &amp;Script…</source>
        <translation>运行脚本(&amp;S)…</translation>
    </message>
    <message>
        <source>Replay a script of painting operations on the open model</source>
        <translation>在打开的模型上回放绘制操作脚本</translation>
    </message>
    <message>
        <source>Copy Session as &amp;Script</source>
        <translation>将会话复制为脚本(&amp;S)</translation>
    </message>
    <message>
        <source>Copy what you did since opening the model as a script that reproduces it (for bug reports and automation)</source>
        <translation>将打开模型以来的操作复制为可重现它的脚本（用于错误报告和自动化）</translation>
    </message>
    <message numerus="yes">
        <source>Copied %n operation(s) as a script</source>
        <translation>
            <numerusform>已将 %n 个操作复制为脚本</numerusform>
        </translation>
    </message>
    <message>
        <source>Run Script</source>
        <translation>运行脚本</translation>
    </message>
    <message>
        <source>Scripts (*.json);;All files (*)</source>
        <translation>脚本 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <source>The script cannot be run: %1</source>
        <translation>无法运行脚本：%1</translation>
    </message>
    <message numerus="yes">
        <source>Run %n operation(s) of %1 on the open model?</source>
        <translation>
            <numerusform>在打开的模型上运行 %1 中的 %n 个操作？</numerusform>
        </translation>
    </message>
    <message>
        <source>As &amp;One Undo Step</source>
        <translation>作为一个撤销步骤(&amp;O)</translation>
    </message>
    <message>
        <source>&amp;Step by Step</source>
        <translation>逐步(&amp;S)</translation>
    </message>
    <message>
        <source>Running the script…</source>
        <translation>正在运行脚本…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message numerus="yes">
        <source>cancelled after %n operation(s)</source>
        <translation>
            <numerusform>在 %n 个操作后已取消</numerusform>
        </translation>
    </message>
    <message>
        <source>Script finished</source>
        <translation>脚本已完成</translation>
    </message>
    <message>
        <source>Script stopped: %1</source>
        <translation>脚本已停止：%1</translation>
    </message>
</context>
<context>
    <name>ui::SegmentationControls</name>
    <message>
        <source>Depth threshold</source>
        <translation>深度阈值</translation>
    </message>
    <message>
        <source>How far apart in depth two neighbouring pixels may be and still count as one surface, as a fraction of the model&apos;s longest side.
Smaller splits the view into more regions.</source>
        <translation>两个相邻像素在深度上最多相差多少仍被视为同一表面，以模型最长边的比例表示。
数值越小，视图被分成的区域越多。</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>重置</translation>
    </message>
    <message>
        <source>Back to the default threshold (%1)</source>
        <translation>恢复默认阈值（%1）</translation>
    </message>
    <message>
        <source>Surface</source>
        <translation>表面</translation>
    </message>
    <message>
        <source>Plain depth</source>
        <translation>纯深度</translation>
    </message>
    <message>
        <source>Follows each triangle&apos;s plane: sloped surfaces stay one region at any threshold</source>
        <translation>沿每个三角形的平面判断：倾斜的表面在任何阈值下都保持为一个区域</translation>
    </message>
    <message>
        <source>The paper&apos;s test: depth difference below the threshold; steep surfaces break apart</source>
        <translation>论文中的测试：深度差低于阈值；陡峭的表面会被分开</translation>
    </message>
    <message>
        <source>How neighbouring pixels are judged to lie on one surface</source>
        <translation>如何判断相邻像素位于同一表面</translation>
    </message>
    <message>
        <source>Capture back faces (two-sided)</source>
        <translation>捕获背面（双面）</translation>
    </message>
    <message>
        <source>Show, paint and split into depth layers the back faces of every surface. Without it, back faces are hidden but for the open surfaces of double-sided materials (a leaf, a cloth). Changing it captures the view again.</source>
        <translation>显示、绘制所有表面的背面并将其分成深度层。关闭时背面隐藏，双面材质的开放表面（如树叶、布料）除外。更改后会重新捕获视图。</translation>
    </message>
    <message>
        <source>Threshold:</source>
        <translation>阈值：</translation>
    </message>
    <message>
        <source>Test:</source>
        <translation>测试：</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>自动</translation>
    </message>
    <message>
        <source>C++ (processor)</source>
        <translation>C++（处理器）</translation>
    </message>
    <message>
        <source>Compute shader (graphics card)</source>
        <translation>计算着色器（显卡）</translation>
    </message>
    <message>
        <source>Where pixel connectivity is computed; both give the same result, Automatic picks the faster for this computer</source>
        <translation>像素连通性的计算位置；两者结果相同，“自动”会选择在本机上更快的一种</translation>
    </message>
    <message>
        <source>Connectivity:</source>
        <translation>连通性：</translation>
    </message>
    <message>
        <source>Automatic (%1)</source>
        <translation>自动（%1）</translation>
    </message>
</context>
<context>
    <name>ui::StabilizerBox</name>
    <message>
        <source>Stroke sta&amp;bilizer</source>
        <translation>笔画稳定器(&amp;B)</translation>
    </message>
    <message>
        <source>The brush follows the pointer on a string: small wobbles never reach the stroke, for pen and mouse alike</source>
        <translation>画笔用一根绳子跟随指针：细小的抖动不会进入笔画，数位笔和鼠标都一样</translation>
    </message>
    <message>
        <source> px</source>
        <translation> 像素</translation>
    </message>
    <message>
        <source>Length of the string: how far the pointer moves before the brush follows</source>
        <translation>绳子的长度：指针移动多远之后画笔才跟随</translation>
    </message>
    <message>
        <source>Len&amp;gth</source>
        <translation>长度(&amp;G)</translation>
    </message>
    <message>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <source>Averages the pointer&apos;s positions before the string pulls: 0 takes each as it comes</source>
        <translation>在绳子拉动之前对指针位置取平均：0 表示逐个直接使用</translation>
    </message>
    <message>
        <source>Smoothi&amp;ng</source>
        <translation>平滑(&amp;N)</translation>
    </message>
    <message>
        <source>C&amp;atch up at release</source>
        <translation>松开时追上(&amp;A)</translation>
    </message>
    <message>
        <source>On release the stroke goes on to where the pointer is; off, it ends where the brush was</source>
        <translation>松开时笔画延续到指针所在处；关闭时笔画在画笔所在处结束</translation>
    </message>
</context>
<context>
    <name>ui::SymmetryBox</name>
    <message>
        <source>Symmetry</source>
        <translation>对称</translation>
    </message>
    <message>
        <source>Every dab is repeated on the mirrored or turned surface, also where that side is hidden or faces away in this view</source>
        <translation>每个笔触都会在镜像或旋转后的表面上重复，即使该面在此视图中被遮挡或背向相机</translation>
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
        <translation>沿垂直于此轴的模型平面镜像</translation>
    </message>
    <message>
        <source>Mirror</source>
        <translation>镜像</translation>
    </message>
    <message>
        <source>Bounding-box centre</source>
        <translation>包围盒中心</translation>
    </message>
    <message>
        <source>Origin</source>
        <translation>原点</translation>
    </message>
    <message>
        <source>Where the mirror planes and the radial axis pass through</source>
        <translation>镜像平面和径向轴经过的位置</translation>
    </message>
    <message>
        <source>Centre</source>
        <translation>中心</translation>
    </message>
    <message>
        <source>Copies turned about the axis, the stroke included; 1 for none</source>
        <translation>绕轴旋转的副本数（含笔画本身）；1 表示无</translation>
    </message>
    <message>
        <source>X axis</source>
        <translation>X 轴</translation>
    </message>
    <message>
        <source>Y axis</source>
        <translation>Y 轴</translation>
    </message>
    <message>
        <source>Z axis</source>
        <translation>Z 轴</translation>
    </message>
    <message>
        <source>Radial</source>
        <translation>径向</translation>
    </message>
</context>
<context>
    <name>ui::TextureExportDialog</name>
    <message>
        <source>Export Textures</source>
        <translation>导出纹理</translation>
    </message>
    <message>
        <source>&amp;Preset:</source>
        <translation>预设(&amp;P)：</translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation>浏览(&amp;B)…</translation>
    </message>
    <message>
        <source>&amp;Folder:</source>
        <translation>文件夹(&amp;F)：</translation>
    </message>
    <message>
        <source>F&amp;ormat:</source>
        <translation>格式(&amp;O)：</translation>
    </message>
    <message>
        <source>&amp;Bit depth:</source>
        <translation>位深(&amp;B)：</translation>
    </message>
    <message>
        <source>&amp;Normal map:</source>
        <translation>法线贴图(&amp;N)：</translation>
    </message>
    <message>
        <source>Pa&amp;dding:</source>
        <translation>边缘填充(&amp;D)：</translation>
    </message>
    <message>
        <source>&amp;Size:</source>
        <translation>尺寸(&amp;S)：</translation>
    </message>
    <message>
        <source>Files to write:</source>
        <translation>将写出的文件：</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>导出(&amp;E)</translation>
    </message>
    <message>
        <source>glTF metallic-roughness</source>
        <translation>glTF 金属度-粗糙度</translation>
    </message>
    <message>
        <source>Unreal Engine</source>
        <translation>Unreal Engine</translation>
    </message>
    <message>
        <source>Unity (URP, HDRP)</source>
        <translation>Unity（URP、HDRP）</translation>
    </message>
    <message>
        <source>ORM (Godot, Blender)</source>
        <translation>ORM（Godot、Blender）</translation>
    </message>
    <message>
        <source>From a Preset File…</source>
        <translation>从预设文件…</translation>
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
        <translation>OpenGL（Y 向上：glTF、Unity、Godot、Blender）</translation>
    </message>
    <message>
        <source>DirectX (Y down: Unreal Engine)</source>
        <translation>DirectX（Y 向下：Unreal Engine）</translation>
    </message>
    <message>
        <source> texels</source>
        <translation> 纹素</translation>
    </message>
    <message>
        <source>How far the colours at the edges of the UV charts are grown into the empty space, so that mipmaps show no seams</source>
        <translation>UV 块边缘的颜色向空白区域扩展多远，使 mipmap 不出现接缝</translation>
    </message>
    <message>
        <source>Fill all empty space</source>
        <translation>填满所有空白区域</translation>
    </message>
    <message>
        <source>Each texture set&apos;s own</source>
        <translation>各纹理集自身的尺寸</translation>
    </message>
    <message>
        <source>%1 × %1</source>
        <translation>%1 × %1</translation>
    </message>
    <message>
        <source>16-bit float (half)</source>
        <translation>16 位浮点（half）</translation>
    </message>
    <message>
        <source>32-bit float</source>
        <translation>32 位浮点</translation>
    </message>
    <message>
        <source>8-bit</source>
        <translation>8 位</translation>
    </message>
    <message>
        <source>16-bit</source>
        <translation>16 位</translation>
    </message>
    <message>
        <source>The model has no texture set to export: it is painted with vertex colours.</source>
        <translation>模型没有可导出的纹理集：它用顶点颜色绘制。</translation>
    </message>
    <message>
        <source>Choose the folder to write the files into.</source>
        <translation>请选择写入文件的文件夹。</translation>
    </message>
    <message>
        <source>Export Textures To</source>
        <translation>导出纹理到</translation>
    </message>
    <message>
        <source>Texture Export Preset</source>
        <translation>纹理导出预设</translation>
    </message>
    <message>
        <source>Export presets (*.json)</source>
        <translation>导出预设 (*.json)</translation>
    </message>
</context>
<context>
    <name>ui::UnitSpinBox</name>
    <message>
        <source>Off</source>
        <translation>关闭</translation>
    </message>
</context>
<context>
    <name>ui::Viewport</name>
    <message>
        <source>The depth-layer capture is not available.</source>
        <translation>深度层捕获不可用。</translation>
    </message>
    <message>
        <source>LayerPaint needs OpenGL 4.5, but this system provides OpenGL %1.%2.</source>
        <translation>LayerPaint 需要 OpenGL 4.5，但本系统只提供 OpenGL %1.%2。</translation>
    </message>
    <message>
        <source>The renderer could not start: %1</source>
        <translation>渲染器无法启动：%1</translation>
    </message>
    <message>
        <source>The depth-layer views could not start: %1</source>
        <translation>深度层视图无法启动：%1</translation>
    </message>
    <message>
        <source>The depth layers cannot be shown: %1</source>
        <translation>无法显示深度层：%1</translation>
    </message>
    <message>
        <source>Roughness</source>
        <translation>粗糙度</translation>
    </message>
    <message>
        <source>Metallic</source>
        <translation>金属度</translation>
    </message>
    <message>
        <source>Mask (black hides, white shows)</source>
        <translation>蒙版（黑色隐藏，白色显示）</translation>
    </message>
    <message>
        <source>Preparing the model for display…</source>
        <translation>正在准备显示模型…</translation>
    </message>
    <message>
        <source>The model cannot be drawn: there is not enough memory for its GL buffers.</source>
        <translation>无法绘制模型：内存不足，无法容纳其 GL 缓冲区。</translation>
    </message>
</context>
</TS>

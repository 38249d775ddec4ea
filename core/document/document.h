// SPDX-License-Identifier: GPL-3.0-or-later
// core/document/: the controller both programs drive: the Document, its History, scripts
// and the session log, the project state, brush presets.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "core/base/progress.h"
#include "core/depth/depth_layers.h"
#include "core/document/history.h"
#include "core/document/session_log.h"
#include "core/model/camera.h"
#include "core/model/mesh.h"
#include "core/model/mesh_topology.h"
#include "core/paint/brush/dab.h"
#include "core/paint/targets/flood_fill.h"
#include "core/paint/targets/layout_target.h"
#include "core/paint/targets/paint_target.h"
#include "core/paint/tracking/stroke_stabilizer.h"
#include "core/paint/tracking/stroke_tracker.h"
#include "core/regions/region_order.h"

namespace core {

/**
 * The controller (docs/architecture.md): the open model, its camera, the current view's layers
 * and the operations on them, with the one undo history of everything a user changes. The GUI,
 * scripts and the headless tool drive the same object. The mesh and its topology are immutable
 * once set and shared, so worker threads can read them while the GUI goes on.
 */
class Document {
public:
    Document();
    // The stroke tracker refers back to this object.
    Document(const Document&) = delete;
    Document& operator=(const Document&) = delete;

    /**
     * Replaces the model (its topology is computed here); drops the layers and puts the camera in
     * the model's default view (resetCamera()).
     */
    void setMesh(Mesh mesh, std::string name);
    /** setMesh() with mesh's topology made already (buildMeshTopology() of this mesh). */
    void setMesh(Mesh mesh, std::string name, std::shared_ptr<const MeshTopology> topology);
    /** The same with the mesh shared already (a paint target made for it can be adopted). */
    void setMesh(std::shared_ptr<const Mesh> mesh, std::string name,
                 std::shared_ptr<const MeshTopology> topology);
    /**
     * The default view of the model: perspective, looking along -Z with Y up, its bounding
     * sphere framed with kFrameMargin for the view aspect (setViewAspect()).
     */
    void resetCamera();
    /** Width / height of the view the camera is framed for (1 until set); ignored unless > 0. */
    void setViewAspect(float aspect);
    float viewAspect() const { return m_viewAspect; }
    const Mesh& mesh() const { return *m_mesh; }
    std::shared_ptr<const Mesh> sharedMesh() const { return m_mesh; }
    const MeshTopology& topology() const { return *m_topology; }
    std::shared_ptr<const MeshTopology> sharedTopology() const { return m_topology; }
    const std::string& name() const { return m_name; }
    /** Changes whenever the mesh is replaced. */
    std::uint64_t meshSerial() const { return m_meshSerial; }

    Camera& camera() { return m_camera; }
    const Camera& camera() const { return m_camera; }

    const DepthLayerOptions& depthLayerOptions() const { return m_depthLayerOptions; }
    /**
     * Sets the build_layers options. A new threshold or connection test re-segments the current
     * layers at once (no capture); a new capture option (cullBackFaces) drops them.
     */
    void setDepthLayerOptions(const DepthLayerOptions& options);

    /**
     * The connectivity engine used by buildDepthLayers() and re-segmentation on this thread
     * (nullptr: the CPU reference). Not owned; it must outlive its use here.
     */
    void setConnectivityEngine(ConnectivityEngine* engine) { m_engine = engine; }
    /** build_layers for view, synchronously. Keeps the old layers if the capture fails. */
    Status buildDepthLayers(DepthCapturer& capturer, const View& view);
    /**
     * Adopts layers finished elsewhere (see finishDepthLayers()); ignored and false when they were
     * made for another mesh (meshSerial) or with other options, so a stale result is never used.
     */
    bool adoptLayers(DepthLayers layers, std::uint64_t meshSerial);
    /** The current view's layers, or nullptr before the first build or after a change. */
    const DepthLayers* depthLayers() const { return m_depthLayers.get(); }
    /** Drops the layers, e.g. when the view changes (they describe the old view). */
    void clearDepthLayers();

    // Region order (docs/architecture.md §3 step 3), of the current layers; a new build or
    // re-segmentation starts from the initial order (region ids change).

    const RegionOrder& regionOrder() const { return m_order; }
    /**
     * Replaces the order without recording a step (benchmarks, tests); ignored unless it has the
     * layers' regions. User changes go through the operations below, which are undoable.
     */
    void setRegionOrder(RegionOrder order);
    /** The order's ranks (RegionOrder::ranks()), kept up to date. */
    const std::vector<std::uint32_t>& regionRanks() const { return m_ranks; }
    /**
     * The fragment drawn at pixel (y * width + x of the layers' view): the one whose region comes
     * first in the order, skipping hidden regions. kNone on background, outside the view or
     * without layers.
     */
    std::uint32_t visibleFragment(std::size_t pixel) const;
    /**
     * The depth layer shown alone (the single-layer display), 0 for the region order's picture.
     * While one is shown, the fragment drawn at a pixel, and so what strokes, fills, the
     * eyedropper and pop-up clicks start from, is the pixel's fragment on that layer (none
     * where it has none or its region is hidden).
     */
    void setShownLayer(std::uint32_t layer) { m_shownLayer = layer; }
    std::uint32_t shownLayer() const { return m_shownLayer; }
    /** Changes whenever the layers are replaced or re-segmented (region ids change). */
    std::uint64_t depthLayersSerial() const { return m_depthLayersSerial; }
    /** Changes with every change of the order (pop-up, hiding, reset, new layers). */
    std::uint64_t regionOrderSerial() const { return m_orderSerial; }
    /**
     * Intentional pop-up at a window pixel (the paper's click): the region below the visible
     * fragment comes to the front with its neighbours; repeated clicks cycle through the pixel's
     * regions. Returns the region popped up, kNone on background or without layers.
     */
    std::uint32_t popUpAt(glm::vec2 pixel);
    /** Intentional pop-up of a region (a click in the region graph); false if unknown. */
    bool popUpRegion(std::uint32_t region);
    /**
     * Automatic pop-up while painting (default on): a layer-aware dab whose centre is on a
     * fragment that is not the visible one pops that fragment's region up.
     */
    void setAutoPopUp(bool on) { m_autoPopUp = on; }
    bool autoPopUp() const { return m_autoPopUp; }
    /**
     * Paint-to-hide: hides every region visible (in the order given by ranks, e.g. the order at
     * the start of the hiding stroke, so a stroke does not drill through what it reveals) at a
     * pixel whose centre lies within radius of the segment from a to b. Returns how many
     * regions were hidden.
     */
    std::size_t hideAlong(glm::vec2 a, glm::vec2 b, float radius,
                          std::span<const std::uint32_t> ranks);
    /**
     * A paint-to-hide stroke: hideAlong() calls between beginHide() and endHide() use the order
     * at beginHide() and make one undo step.
     */
    void beginHide();
    std::size_t hideAlong(glm::vec2 a, glm::vec2 b, float radius);
    void endHide();
    bool inHide() const { return m_hideRanks.has_value(); }
    /** Shows hidden regions again (one undo step); false if none of them was hidden. */
    bool unhideRegions(std::span<const std::uint32_t> regions);
    bool unhideAll();
    /** Back to the initial order (layer, then id; one undo step); false if it already was. */
    bool resetRegionOrder();
    /**
     * The world point of the visible fragment at a window pixel (the pivot of layer-aware
     * rotation), from its view depth; nullopt on background or without layers.
     */
    std::optional<glm::vec3> surfacePoint(glm::vec2 pixel) const;
    /**
     * The eyedropper: the unlit surface colour (linear RGBA) of the visible fragment at pixel, as
     * the paint target holds it (painted texel or vertex colour) where the pixel centre's ray
     * meets the fragment's triangle. Creates the paint target if there is none yet. nullopt on
     * background, outside the view, without layers, or when the target cannot be made.
     */
    std::optional<glm::vec4> pickColor(std::size_t pixel);

    // Painting (docs/architecture.md §3 steps 5-6).

    Brush& brush() { return m_brush; }
    const Brush& brush() const { return m_brush; }
    /** How pen pressure maps to the brush (applied to every stroke point's pressure). */
    const PressureCurve& pressureCurve() const { return m_pressureCurve; }
    void setPressureCurve(const PressureCurve& curve) { m_pressureCurve = curve; }
    /** Layer-aware (the paper's strokes across layers) or conventional (front surface only). */
    void setLayerAware(bool on) { m_tracker.setLayerAware(on); }
    bool layerAware() const { return m_tracker.layerAware(); }
    /**
     * The paint target, created on first use with options (a texture for meshes with UVs, vertex
     * colours otherwise; a texture asked for on a mesh without UVs gets an automatic UV layout,
     * made on this thread), or the Error saying why it cannot be made.
     */
    Result<PaintTarget*> ensurePaintTarget();
    /** ensurePaintTarget() for callers that only need to know whether there is one: nullptr. */
    PaintTarget* paintTarget();
    /**
     * Replaces the paint target with one made with options: an undo step (the old target is
     * kept in it) when there was a target. A texture on a mesh without UVs is painted over an
     * automatic UV layout (makeLayoutTarget(); progress reports it, its false cancels). On
     * failure nothing changes.
     */
    Status setPaintTarget(const PaintTargetOptions& options, const ProgressFn& progress = {});
    /**
     * setPaintTarget() with a target made elsewhere (e.g. off the GUI thread by
     * makePaintTargetWithLayout()) from this document's mesh at meshSerial with options. An
     * Error, and nothing changes, when the mesh has been replaced since or the target is not one
     * of its triangles. A target made before the document had a mesh to paint (as a model loads)
     * is not an undo step.
     */
    /**
     * adoptPaintTarget() of the target made with the model as it loaded (off the GUI thread),
     * right after setMesh(): it stands for the one ensurePaintTarget() would make on first use, so
     * choosing another target (setPaintTarget(), adoptPaintTarget()) before anything was done (no
     * history change since) is no undo step either; raising its texture size is one.
     */
    Status adoptModelPaintTarget(std::unique_ptr<PaintTarget> target,
                                 const PaintTargetOptions& options);
    Status adoptPaintTarget(std::unique_ptr<PaintTarget> target, const PaintTargetOptions& options,
                            std::uint64_t meshSerial);
    /**
     * Raises the size of the texture material is painted into to width (its height in
     * proportion), the page resampled with what is painted on it: an undo step that swaps the
     * paint target, as setPaintTarget() does. Every material on that page gets the new size.
     * An Error, and nothing changes, when the target is not a texture, the material does not
     * exist, width is not larger than the page (or beyond 8192), or paint layers exist (their
     * planes are not resampled: merge or delete them first).
     */
    Status raiseTextureSize(std::uint32_t material, int width);
    /**
     * The target a mesh without UVs gets unless the user chooses: defaultTargetKind() for the
     * default brush (a texture with an automatic layout where vertex colours would be coarse).
     */
    PaintTargetKind suggestedPaintTargetKind() const;
    /** Changes whenever the paint target object is replaced (made, set, undone, redone). */
    std::uint64_t paintTargetSerial() const { return m_targetSerial; }
    /**
     * The options the next paint target is made with. setPaintOptions() keeps the current
     * target; the options apply when one is made next (after setMesh(), or on first use).
     */
    const PaintTargetOptions& paintOptions() const { return m_paintOptions; }
    void setPaintOptions(const PaintTargetOptions& options) { m_paintOptions = options; }
    bool hasPaintTarget() const { return m_paintTarget != nullptr; }
    /** The paint target if there is one (never makes one). */
    const PaintTarget* currentPaintTarget() const { return m_paintTarget.get(); }
    /** The options the paint target is (or will be) made with. */
    const PaintTargetOptions& paintTargetOptions() const { return m_paintOptions; }
    /** The current paint target's kind; before one exists, the kind it will have. */
    PaintTargetKind paintTargetKind() const;
    /**
     * Starts a stroke (On-Mouse-Down) at a pixel of the current layers' view and paints its first
     * dab. point.pressure is the pen's, before the pressure curve. Needs layers (an Error
     * otherwise); a point on background starts nothing. changes receives what was painted, for
     * the GPU copy.
     */
    Status beginStroke(const StrokePoint& point, PaintChanges& changes);
    /** On-Mouse-Drag: tracks and paints the dabs up to point; changes gets what they touched. */
    void moveStroke(const StrokePoint& point, PaintChanges& changes);
    /**
     * Ends the stroke and records it, with the pop-ups it caused, as one undo step. A stabilized
     * stroke with catch-up (Brush::stabilizerCatchUp) first paints on to the last input point;
     * changes receives what that painted.
     */
    void endStroke(PaintChanges& changes);
    void endStroke();
    bool inStroke() const { return m_tracker.inStroke(); }
    /**
     * The stroke stabilizer of the stroke in progress (Brush::stabilizer): the input points of
     * beginStroke() and moveStroke() pass through it, so the GUI and scripts share it; the GUI
     * draws its string from here.
     */
    const StrokeStabilizer& stabilizer() const { return m_stabilizer; }
    /**
     * A straight line (Shift+click) from the end of the previous stroke or line to point, as one
     * undo step: tracked like a stroke, layer-aware from the depth layer the previous stroke
     * ended on, so a line can run on behind an occluder. Without a previous stroke in this
     * view it paints one dab at point. Needs layers (an Error otherwise).
     */
    Status lineTo(const StrokePoint& point, PaintChanges& changes);
    /** A straight line from from (starting on the surface visible there) to to; one step. */
    Status line(const StrokePoint& from, const StrokePoint& to, PaintChanges& changes);
    /** Where the next lineTo() starts (the last dab of the previous stroke), if anywhere. */
    std::optional<glm::vec2> lineStart() const {
        return m_lineStart ? std::optional<glm::vec2>(m_lineStart->position) : std::nullopt;
    }
    /** Dabs painted by the last beginStroke()/moveStroke() and the time spent on the target. */
    struct DabStats {
        std::size_t dabs = 0;
        double targetMs = 0.0;
    };
    const DabStats& lastDabStats() const { return m_dabStats; }
    /**
     * The views the symmetric copies of the brush (Brush::symmetry) are painted through, made
     * for the current layers: at the first symmetric stroke (captured on the CPU on this thread),
     * or ahead of it elsewhere (symmetryBuild(), adoptSymmetry()); empty without symmetry.
     */
    std::vector<const DepthLayers*> symmetryLayers() const;

    /**
     * What the symmetric copies' layers are made from: the views of the copies of the current
     * layers' view, with the mesh shared, so build() can run on any thread while the document
     * goes on. Adopted only while the layers, the model and the symmetry are still these.
     */
    struct SymmetryBuild {
        BrushSymmetry symmetry;
        std::uint64_t depthLayersSerial = 0;
        std::uint64_t meshSerial = 0;
        std::shared_ptr<const Mesh> mesh;
        std::shared_ptr<const MeshTopology> topology;
        DepthLayerOptions options;
        std::vector<glm::mat4> transforms;
        std::vector<View> views;
        std::vector<std::optional<DepthLayers>>
            layers; // per view, after build(); none if it failed
        /**
         * Captures (on the CPU) and finishes every view's layers; progress gets the fraction of
         * copies done and stops the build (false, nothing built) when it returns false.
         */
        bool build(const ProgressFn& progress, ConnectivityEngine* engine = nullptr);
    };
    /** The build the copies need before the next symmetric stroke; nullopt when ready or off. */
    std::optional<SymmetryBuild> symmetryBuild() const;
    /** Whether a symmetric stroke now has its copies' layers (true without symmetry). */
    bool symmetryReady() const { return !symmetryBuild(); }
    /** Adopts a finished build; ignored and false when it is stale (or not built). */
    bool adoptSymmetry(SymmetryBuild build);
    /**
     * Whether a stroke builds missing copies itself (on this thread, the default: scripts and the
     * headless tool). Off, a stroke whose copies are not ready paints without them: the GUI
     * builds them in the background and waits for them before a stroke starts.
     */
    void setSymmetryBuiltOnStroke(bool onStroke) { m_symmetryOnStroke = onStroke; }
    const StrokeTracker& strokeTracker() const { return m_tracker; }
    /**
     * The paper's Figure 4 overlay of the last dab's maps (StrokeTracker::fillOverlay: Mp red,
     * the rest of Mt blue); false if rgba is not 4 bytes a pixel of the layers' view.
     */
    bool fillBrushMaps(std::span<std::uint8_t> rgba, std::uint8_t alpha = 128) {
        return m_tracker.fillOverlay(rgba, alpha);
    }
    /**
     * Flood fill (the Fill tool) at a window position of the current layers' view with the brush
     * colour and opacity, as one undo step. mode says what is filled (FillMode), starting from
     * the visible fragment there; tolerance (0..1) is FillMode::Color's. Needs layers (an Error
     * otherwise); background or a position outside the view fills nothing. changes receives
     * what was painted.
     */
    Status fill(glm::vec2 position, FillMode mode, float tolerance, PaintChanges& changes);
    /**
     * Undo / redo of the newest step of any kind; false when there is nothing to undo / redo.
     * changes receives the paint it touched; the region order and the paint target report
     * their own changes (regionOrderSerial(), paintTargetSerial()).
     */
    bool undo(PaintChanges& changes);
    bool redo(PaintChanges& changes);
    const History& history() const { return m_history; }
    History& history() { return m_history; }

    // Paint layers of a texture target (docs/architecture.md §3 step 6). Each operation makes the
    // target if there is none yet, is one undo step (StepKind::PaintLayers), is written to the
    // session log, and puts what the composite changed in changes. Paint layers are named by id
    // (PaintLayer::id); index 0 is the layer right above the base. An Error (nothing changed)
    // for a vertex colour target, an unknown id or an operation that does not apply.

    /** The texture target (made on first use), or an Error for a vertex colour target. */
    Result<PaintLayerTarget*> paintLayerTarget();
    /**
     * Adds a layer right above the selected one (above the base: at the bottom) and selects it.
     * Returns its id.
     */
    Result<std::uint64_t> addPaintLayer(PaintLayerSettings settings, PaintChanges& changes);
    /** A copy right above layer id, selected. Returns its id. */
    Result<std::uint64_t> duplicatePaintLayer(std::uint64_t id, PaintChanges& changes);
    /** Deletes layer id; the selection moves to the layer below it (or the base). */
    Status deletePaintLayer(std::uint64_t id, PaintChanges& changes);
    /** Moves layer id to index (clamped to the stack). */
    Status movePaintLayer(std::uint64_t id, std::size_t index, PaintChanges& changes);
    /** Name, opacity, blend mode, visibility, lock transparency, fill values of layer id. */
    Status setPaintLayerSettings(std::uint64_t id, PaintLayerSettings settings,
                                 PaintChanges& changes);
    /** Merges layer id into the one below (PaintLayerStack::mergeDown()), which is selected. */
    Status mergePaintLayerDown(std::uint64_t id, PaintChanges& changes);
    /** Flattens every layer into one (PaintLayerStack::flatten()), which is selected. */
    Status flattenPaintLayers(std::string name, PaintChanges& changes);
    /** Gives layer id a mask (all showing) and selects the mask. */
    Status addPaintLayerMask(std::uint64_t id, PaintChanges& changes);
    /**
     * The fill layer painting would go into (selected, its mask not), or nullptr: its values are
     * uniform, so strokes and fills refuse it with a reason (paint its mask, or a paint layer).
     */
    const PaintLayer* selectedFillLayer() const;
    /** Removes the mask of layer id. */
    Status deletePaintLayerMask(std::uint64_t id, PaintChanges& changes);
    /**
     * Where painting goes: the base (layer 0), a layer, or its mask. Logged in the session but no
     * undo step; undoing an operation brings back the selection it found.
     */
    Status selectPaint(PaintSelection selection);
    /** What the user did since the model was set, as a script that reproduces it. */
    const SessionLog& session() const { return m_session; }
    /**
     * The model as painted: target pages as textures or painted vertex colours, on the target's
     * mesh (with the automatic layout's UVs when it made one).
     */
    Mesh paintedMesh() const;

private:
    void paintDabs(PaintChanges& changes);
    /** What line() and lineTo() do first: ends a stroke, logs op; an error without layers. */
    Status startLine(nlohmann::json op, PaintChanges& changes);
    /** The straight stroke of line() and lineTo(), starting on layer (0: the visible one). */
    Status paintLine(const StrokePoint& from, std::uint32_t layer, const StrokePoint& to,
                     PaintChanges& changes);
    /** Records the stroke painted on the target as one step (with its pop-ups). */
    void pushStrokeStep();
    /** point with the pressure curve applied. */
    StrokePoint curved(StrokePoint point) const;
    /** Applies a paint-layer change (both directions: it swaps), adding what changed. */
    void applyPaintLayerChange(PaintLayerChange& change, PaintChanges& changes);
    /** Applies change, records it as a step and logs op. */
    void pushPaintLayerChange(PaintLayerChange change, nlohmann::json op, PaintChanges& changes);
    /** The index of layer id in the texture target's stack, or an Error. */
    Result<std::size_t> paintLayerIndex(std::uint64_t id);
    /** Applies (undo) or re-applies (redo) one step's parts. */
    void applyStep(HistoryStep& step, bool undo, PaintChanges& changes);
    /**
     * What painting (a stroke, a fill) needs: built layers and the paint target (made on first
     * use), and somewhere paint can go (not a fill layer); a stroke in progress is ended.
     */
    Result<PaintTarget*> readyToPaint();
    /**
     * Makes target current (with options); an undo step when it replaces one, logged as
     * operation (a set-target of options when empty).
     */
    void installPaintTarget(std::unique_ptr<PaintTarget> target, const PaintTargetOptions& options,
                            nlohmann::json operation = {});
    /** undo() or redo(): ends a stroke or hide in progress, applies the next step, logs it. */
    bool walkHistory(bool undo, PaintChanges& changes);
    /** Records the order change since before as a step of kind (nothing if unchanged). */
    void pushOrderStep(StepKind kind, RegionOrderState before);
    /** The layers were replaced or re-segmented: a fresh order, the tracker told. */
    void layersChanged();
    void orderChanged();
    /**
     * Readies the symmetric copies for a stroke (document_symmetry.cpp): their views' layers
     * (built when the layers, the model or the symmetry changed) and fresh trackers.
     */
    void startSymmetry();
    /** Paints the symmetric copies of dab, adding what they touched to changes. */
    void paintCopies(const Dab& dab, PaintChanges& changes);
    /** Automatic pop-up of the region under a dab's centre when it is not the visible one. */
    void popUpUnder(const Dab& dab);
    /** y * width + x of a window pixel of the layers' view, or nullopt outside it. */
    std::optional<std::size_t> pixelIndex(glm::vec2 pixel) const;

    std::shared_ptr<const Mesh> m_mesh;
    std::shared_ptr<const MeshTopology> m_topology;
    std::string m_name;
    std::uint64_t m_meshSerial = 0;
    Camera m_camera;
    float m_viewAspect = 1.0f;
    DepthLayerOptions m_depthLayerOptions;
    ConnectivityEngine* m_engine = nullptr;
    std::unique_ptr<DepthLayers> m_depthLayers;
    RegionOrder m_order;
    std::vector<std::uint32_t> m_ranks;
    std::vector<std::uint8_t> m_fragmentHidden; // per fragment, empty when nothing is hidden
    std::uint64_t m_orderSerial = 0;
    std::uint64_t m_depthLayersSerial = 0;
    bool m_autoPopUp = true;
    std::optional<std::vector<std::uint32_t>> m_hideRanks; // during a paint-to-hide stroke
    RegionOrderState m_hideBefore;
    RegionOrderState m_strokeOrderBefore;
    std::uint32_t m_shownLayer = 0;

    Brush m_brush;
    PressureCurve m_pressureCurve;
    StrokeTracker m_tracker;
    StrokeStabilizer m_stabilizer;
    /** The last dab of a stroke: where a straight line goes on from. */
    struct LineStart {
        glm::vec2 position{0.0f};
        std::uint32_t layer = 0; // 0: conventional, start on the visible surface
    };
    std::optional<LineStart> m_strokeEnd; // of the stroke in progress
    std::optional<LineStart> m_lineStart; // of the previous stroke
    std::vector<Dab> m_dabs;              // reused between calls
    /** A symmetric copy of the stroke, painted through its own (mirrored or turned) view. */
    struct SymmetryCopy {
        glm::mat4 transform{1.0f};
        bool reflects = false;
        std::unique_ptr<DepthLayers> layers;
        StrokeTracker tracker;
        bool started = false;
    };
    std::vector<std::unique_ptr<SymmetryCopy>> m_copies;
    BrushSymmetry m_copiesSymmetry;       // what m_copies were made for
    std::uint64_t m_copiesLayers = ~0ull; // m_depthLayersSerial they were made for
    std::uint64_t m_copiesMesh = ~0ull;   // m_meshSerial they were made for
    bool m_symmetryOnStroke = true;
    bool m_copiesPaint = false; // the stroke in progress paints m_copies
    std::vector<Dab> m_copyDabs;
    std::vector<MapPixel> m_copyPaintable; // a copy's paintable map storage, reused
    DabStats m_dabStats;
    PaintTargetOptions m_paintOptions;
    std::unique_ptr<PaintTarget> m_paintTarget;
    /** Before another target is chosen: drops the model's target if it is still untouched. */
    void forgetUntouchedModelTarget();
    /** The history's revision when the target made with the model was adopted, if it is that. */
    std::optional<std::uint64_t> m_modelTargetRevision;
    std::uint64_t m_targetSerial = 0;
    History m_history;
    SessionLog m_session;
};

} // namespace core

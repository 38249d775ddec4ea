// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "core/camera.h"
#include "core/dab.h"
#include "core/layers.h"
#include "core/mesh.h"
#include "core/mesh_topology.h"
#include "core/paint_target.h"
#include "core/region_order.h"
#include "core/stroke_tracker.h"
#include "core/undo_tiles.h"

namespace core {

/**
 * The controller (DESIGN.md §2): the open model, its camera, the current view's layers and the
 * operations on them. The GUI and the headless tool drive the same object. The mesh and its
 * topology are immutable once set and shared, so worker threads can read them while the GUI
 * goes on.
 */
class Document {
public:
    Document();
    // The stroke tracker refers back to this object.
    Document(const Document&) = delete;
    Document& operator=(const Document&) = delete;

    /** Replaces the model (its topology is computed here); drops the layers, frames the camera. */
    void setMesh(Mesh mesh, std::string name);
    const Mesh& mesh() const { return *m_mesh; }
    std::shared_ptr<const Mesh> sharedMesh() const { return m_mesh; }
    const MeshTopology& topology() const { return *m_topology; }
    std::shared_ptr<const MeshTopology> sharedTopology() const { return m_topology; }
    const std::string& name() const { return m_name; }
    /** Changes whenever the mesh is replaced. */
    std::uint64_t meshSerial() const { return m_meshSerial; }

    Camera& camera() { return m_camera; }
    const Camera& camera() const { return m_camera; }

    const LayerOptions& layerOptions() const { return m_layerOptions; }
    /**
     * Sets the build_layers options. A new threshold or connection test re-segments the current
     * layers at once (no capture); a new capture option (cullBackFaces) drops them.
     */
    void setLayerOptions(const LayerOptions& options);

    /**
     * The connectivity engine used by buildLayers() and re-segmentation on this thread (nullptr:
     * the CPU reference). Not owned; it must outlive its use here.
     */
    void setConnectivityEngine(ConnectivityEngine* engine) { m_engine = engine; }
    /** build_layers for view, synchronously. Keeps the old layers if the capture fails. */
    Status buildLayers(LayerCapturer& capturer, const View& view);
    /**
     * Adopts layers finished elsewhere (see finishLayers()); ignored and false when they were
     * made for another mesh (meshSerial) or with other options, so a stale result is never used.
     */
    bool adoptLayers(Layers layers, std::uint64_t meshSerial);
    /** The current view's layers, or nullptr before the first build or after a change. */
    const Layers* layers() const { return m_layers.get(); }
    /** Drops the layers, e.g. when the view changes (they describe the old view). */
    void clearLayers();

    // Region order (DESIGN.md §3 step 3), of the current layers; a new build or re-segmentation
    // starts from the initial order (region ids change).

    const RegionOrder& regionOrder() const { return m_order; }
    /** Replaces the order (pop-up, hiding, undo); ignored unless it has the layers' regions. */
    void setRegionOrder(RegionOrder order);
    /** The order's ranks (RegionOrder::ranks()), kept up to date. */
    const std::vector<std::uint32_t>& regionRanks() const { return m_ranks; }
    /**
     * The fragment drawn at pixel (y * width + x of the layers' view): the one whose region comes
     * first in the order, skipping hidden regions. kNone on background, outside the view or
     * without layers.
     */
    std::uint32_t visibleFragment(std::size_t pixel) const;

    // Painting (DESIGN.md §3 steps 5-6).

    Brush& brush() { return m_brush; }
    const Brush& brush() const { return m_brush; }
    /** Layer-aware (the paper's strokes across layers) or conventional (front surface only). */
    void setLayerAware(bool on) { m_tracker.setLayerAware(on); }
    bool layerAware() const { return m_tracker.layerAware(); }
    /**
     * The paint target, created on first use with options (a texture for meshes with UVs, vertex
     * colours otherwise). Returns nullptr and sets error if it cannot be made.
     */
    PaintTarget* paintTarget(std::string* error = nullptr);
    /** Replaces the paint target with one made with options (drops the undo history). */
    Status resetPaintTarget(const PaintTargetOptions& options);
    bool hasPaintTarget() const { return m_paintTarget != nullptr; }
    /**
     * Starts a stroke (On-Mouse-Down) at a pixel of the current layers' view and paints its first
     * dab. Needs layers (an Error otherwise); a point on background starts nothing. changes
     * receives what was painted, for the GPU copy.
     */
    Status beginStroke(const StrokePoint& point, PaintChanges& changes);
    /** On-Mouse-Drag: tracks and paints the dabs up to point; changes gets what they touched. */
    void moveStroke(const StrokePoint& point, PaintChanges& changes);
    /** Ends the stroke and records it for undo. */
    void endStroke();
    bool inStroke() const { return m_tracker.inStroke(); }
    /** Dabs painted by the last beginStroke()/moveStroke() and the time spent on the target. */
    struct DabStats {
        std::size_t dabs = 0;
        double targetMs = 0.0;
    };
    const DabStats& lastDabStats() const { return m_dabStats; }
    const StrokeTracker& strokeTracker() const { return m_tracker; }
    /**
     * The paper's Figure 4 overlay of the last dab's maps (StrokeTracker::fillOverlay: Mp red,
     * the rest of Mt blue); false if rgba is not 4 bytes a pixel of the layers' view.
     */
    bool fillBrushMaps(std::span<std::uint8_t> rgba, std::uint8_t alpha = 128) {
        return m_tracker.fillOverlay(rgba, alpha);
    }
    /** Undo / redo of paint; false when there is nothing to undo / redo. */
    bool undo(PaintChanges& changes);
    bool redo(PaintChanges& changes);
    UndoHistory& history() { return m_history; }
    /** The model as painted: target pages as textures or painted vertex colours. */
    Mesh paintedMesh() const;

private:
    void paintDabs(PaintChanges& changes);
    /** The layers were replaced or re-segmented: a fresh order, the tracker told. */
    void layersChanged();

    std::shared_ptr<const Mesh> m_mesh;
    std::shared_ptr<const MeshTopology> m_topology;
    std::string m_name;
    std::uint64_t m_meshSerial = 0;
    Camera m_camera;
    LayerOptions m_layerOptions;
    ConnectivityEngine* m_engine = nullptr;
    std::unique_ptr<Layers> m_layers;
    RegionOrder m_order;
    std::vector<std::uint32_t> m_ranks;

    Brush m_brush;
    StrokeTracker m_tracker;
    std::vector<Dab> m_dabs; // reused between calls
    DabStats m_dabStats;
    PaintTargetOptions m_paintOptions;
    std::unique_ptr<PaintTarget> m_paintTarget;
    UndoHistory m_history;
};

} // namespace core

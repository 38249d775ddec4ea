// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <memory>
#include <optional>
#include <string_view>

#include "core/base/result.h"
#include "core/depth/connectivity.h"
#include "core/depth/depth_layers.h"
#include "core/depth/depth_stack.h"

namespace render {

/** Where pixel connectivity runs: the core's C++ reference or GpuConnectivity's compute pass. */
enum class ConnectivityBackend { Auto, Cpu, Gpu };

/** "auto", "cpu" or "gpu", as settings and the command line spell it. */
const char* connectivityBackendName(ConnectivityBackend backend);
/** The backend named (case-insensitive), or nothing for an unknown name. */
std::optional<ConnectivityBackend> parseConnectivityBackend(std::string_view name);

/**
 * Cpu or Gpu for a request: Auto is Cpu on a software renderer (its compute shaders run this
 * pass 2–3× slower than the threaded C++ reference) and Gpu on real graphics hardware.
 */
ConnectivityBackend resolveConnectivityBackend(ConnectivityBackend requested,
                                               bool softwareRenderer);

/**
 * core::computeConnectivity as an OpenGL compute pass (shaders/connectivity.comp): uploads the
 * stack and the per-triangle planes, corners and components, runs one invocation per fragment and
 * reads the links back. On llvmpipe the links are byte-identical to the core reference. On other
 * GPUs they can differ where a decision hinges on the last bit of a float: GLSL allows division
 * and square roots a few ulps off and may flush denormals, which the reference does not.
 * Buffers are kept and grown between calls. Needs a current GL 4.5 context for every call, the
 * one it was initialized in.
 */
class GpuConnectivity {
public:
    GpuConnectivity();
    ~GpuConnectivity();
    GpuConnectivity(const GpuConnectivity&) = delete;
    GpuConnectivity& operator=(const GpuConnectivity&) = delete;

    /** Compiles the shader and reads the GL's limits; an Error if either fails. */
    core::Status initialize();
    bool initialized() const;

    /**
     * The links of core::computeConnectivity(stack, options, geometry) (options.threads is
     * ignored), and in ms the milliseconds from an idle GPU to the links in CPU memory (checking
     * and uploading the input, the dispatch, the readback). A stack with a wrong offsets size gives
     * the reference's all-zero result. Returns an Error if initialize() has not succeeded, if the
     * offsets do not ascend to the fragment count, if a buffer would exceed the GL's shader storage
     * limit (128 MiB on llvmpipe: 33 million fragments or 4 million triangles), if GPU memory runs
     * out or the dispatch fails; callers then use the CPU reference.
     */
    core::Result<core::Connectivity> compute(const core::DepthStack& stack,
                                             const core::ConnectivityOptions& options,
                                             const core::SurfaceGeometry* geometry,
                                             double* ms = nullptr);

    /** Frees every GL object; the context must be current. Called by the destructor too. */
    void release();

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

/**
 * Connectivity on the backend that `backend` resolves to for the current context: the compute
 * pass of gpu (which must be initialized and current) or the core reference, which also runs
 * when gpu is null or its pass fails. used, if given, receives the backend that ran.
 */
core::Connectivity computeConnectivity(ConnectivityBackend backend, GpuConnectivity* gpu,
                                       const core::DepthStack& stack,
                                       const core::ConnectivityOptions& options,
                                       const core::SurfaceGeometry* geometry,
                                       ConnectivityBackend* used = nullptr);

/**
 * build_layers' connectivity step on the backend chosen for this machine (docs/architecture.md §2:
 * the faster of the two). Needs the current GL context at construction and for every compute().
 */
class GlConnectivityEngine : public core::ConnectivityEngine {
public:
    /** Resolves Auto by the current renderer; a GPU pass that fails to build falls back to CPU. */
    explicit GlConnectivityEngine(ConnectivityBackend requested = ConnectivityBackend::Auto);
    ~GlConnectivityEngine() override;
    core::Connectivity compute(const core::DepthStack& stack,
                               const core::ConnectivityOptions& options,
                               const core::SurfaceGeometry* geometry) override;
    /** Cpu or Gpu: what runs now. */
    ConnectivityBackend backend() const { return m_backend; }

private:
    ConnectivityBackend m_backend = ConnectivityBackend::Cpu;
    std::unique_ptr<GpuConnectivity> m_gpu;
};

} // namespace render

// SPDX-License-Identifier: GPL-3.0-or-later
// The linker of computeConnectivity() in LAYERPAINT_LINKER_LANES lanes. connectivity.cpp
// includes it once for each lane width, each time inside a namespace of its own (for eight lanes
// with AVX2 enabled for every function in it), after the headers and the helpers it uses; so it
// has no include guard and includes nothing.

constexpr std::uint32_t kLanes = LAYERPAINT_LINKER_LANES;
/** kLanes floats or 32-bit integers in one SIMD register (GCC's and Clang's vectors). */
using FloatsN = float __attribute__((vector_size(4 * kLanes)));
using IntsN = std::int32_t __attribute__((vector_size(4 * kLanes)));
constexpr unsigned kAllLanes = (1u << kLanes) - 1u;
/** Room for a pixel's fragments, rounded up to whole groups of lanes. */
constexpr std::uint32_t kSideRoom = (kMaxLinkedLayers + kLanes - 1) / kLanes * kLanes;

/** |v| lane by lane (NaN stays NaN). */
inline FloatsN absN(FloatsN v) {
    return FloatsN(IntsN(v) & (IntsN{} + 0x7fffffff));
}

/** a where mask is set (all ones), else b. */
inline FloatsN selectN(IntsN mask, FloatsN a, FloatsN b) {
    return FloatsN((IntsN(a) & mask) | (IntsN(b) & ~mask));
}

/** Bit k set where lane k of mask is set (lanes all ones or all zeros). */
inline unsigned bitsN(IntsN mask) {
#if LAYERPAINT_LINKER_LANES == 8
    return unsigned(_mm256_movemask_ps(__m256(mask)));
#elif LAYERPAINT_LINKER_LANES == 4 && defined(__SSE__)
    return unsigned(_mm_movemask_ps(__m128(mask)));
#else
    unsigned bits = 0;
    for (std::uint32_t k = 0; k < kLanes; ++k)
        bits |= (unsigned(mask[k]) & 1u) << k;
    return bits;
#endif
}

/**
 * Fragment pairs of two neighbouring pixels from which all their plane depths are computed at
 * once and the pairs decided in groups of lanes (deep pixels need nearly all of those depths;
 * shallow ones few, and one pair at a time costs them less): a group's worth of pairs in eight
 * lanes, four groups' in four.
 */
constexpr std::uint32_t kDeepPair = kLanes == 8 ? 8 : 16;

/** A group of lanes from p on (any alignment). */
template <typename V, typename T> V loadLanes(const T* p) {
    V v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

/**
 * One of 32 bits for a corner id (its low five bits: the corners of nearby triangles have nearby
 * ids), for a quick test of shared corners.
 */
inline std::uint32_t cornerBit(std::uint32_t corner) {
    return 1u << (corner & 31u);
}

/** The lanes of the group from j0 on that hold one of count fragments. */
inline unsigned lanesOf(std::uint32_t count, std::uint32_t j0) {
    return count - j0 >= kLanes ? kAllLanes : (1u << (count - j0)) - 1u;
}

/**
 * One pixel's fragments (up to kMaxLinkedLayers) with what the test needs, loaded once. Arrays
 * have room for whole groups of lanes; what lies past count is left from earlier pixels.
 */
struct Side {
    std::uint32_t first = 0; // index of the layer-1 fragment
    std::uint32_t count = 0; // fragments considered (capped)
    float depth[kSideRoom] = {};
    std::uint32_t triangle[kSideRoom] = {};
    const SurfaceTriangle* info[kSideRoom] = {}; // nullptr when unknown
    std::uint32_t component[kSideRoom] = {};     // info->component, kept beside the others
    // Of info, for deep pixels (see Linker::pack()): its plane (x, y, z, w; 0 when unknown)
    // and corners, kept beside the others.
    bool packed = false;
    float plane[4][kSideRoom] = {};
    std::uint32_t corner[3][kSideRoom] = {};
    // A bit per corner (cornerBit()); 0 without corners. Two triangles sharing a corner have a
    // bit in common.
    std::uint32_t cornerBits[kSideRoom] = {};
};

/**
 * Plane depths of one side's fragments on one ray, computed on first use within a pixel pair
 * (most pairs never need them: same triangle, or another mesh part). A value is valid while its
 * stamp, or the stamp of all values, equals the pair's.
 */
struct LazyDepths {
    float value[kSideRoom] = {};
    std::uint32_t stamp[kMaxLinkedLayers] = {};
    std::uint32_t all = 0; // the pair for which every fragment's value was computed at once

    float get(const Side& side, std::uint32_t k, const Ray& ray, std::uint32_t now) {
        if (all != now && stamp[k] != now) {
            stamp[k] = now;
            value[k] = planeDepth(side.info[k]->plane, ray);
        }
        return value[k];
    }
};

class Linker {
public:
    Linker(const DepthStack& stack, const ConnectivityOptions& options,
           const SurfaceGeometry* geometry, Connectivity& out)
        : m_stack(stack), m_geometry(options.test == ConnectionTest::Surface ? geometry : nullptr),
          m_rays(m_geometry ? m_geometry->rays : PixelRays{}), m_out(out) {
        if (m_geometry && m_geometry->hasEntries() &&
            m_geometry->fragmentEntry.size() == stack.fragmentCount())
            m_fragmentEntry = m_geometry->fragmentEntry.data();
        const float scale = options.unitScale > 0.0f ? options.unitScale : 1.0f;
        m_limit = options.threshold / scale;
        m_contactLimit = m_limit * std::max(options.contactFactor, 0.0f);
        m_creaseCos = std::cos(glm::radians(std::clamp(options.creaseAngleDegrees, 0.0f, 180.0f)));
        m_smoothCos = std::cos(glm::radians(std::clamp(options.smoothAngleDegrees, 0.0f, 90.0f)));
        m_deepPair = options.batchDeepPixels ? kDeepPair : kNone;
    }

    /**
     * Links the fragments of rows [y0, y1) to their right and down neighbours and back. Each
     * pixel's fragments are loaded once and reused as the left side of the next pair.
     */
    void rows(int y0, int y1) {
        if (m_geometry)
            rowsOf<true>(y0, y1);
        else
            rowsOf<false>(y0, y1);
    }

    /** Whether a pixel loaded so far had more than kMaxLinkedLayers fragments. */
    bool truncated() const { return m_truncated; }

private:
    template <bool kSurface> void rowsOf(int y0, int y1) {
        const int w = m_stack.width, h = m_stack.height;
        Side* cur = &m_sides[0];
        Side* next = &m_sides[1];
        Side* down = &m_sides[2];
        for (int y = y0; y < y1; ++y) {
            bool curLoaded = false;
            for (auto [x, end] = m_stack.rowSpan(y); x < end; ++x) {
                const std::size_t p = std::size_t(y) * std::size_t(w) + std::size_t(x);
                if (m_stack.layerCount(p) == 0) {
                    curLoaded = false;
                    continue;
                }
                if (!curLoaded)
                    load<kSurface>(*cur, p);
                const float px = float(x) + 0.5f, py = float(y) + 0.5f;
                LazyRay rayP{m_rays, px, py}; // shared by both pairs, made if one needs it
                if (y + 1 < h && m_stack.layerCount(p + std::size_t(w)) != 0) {
                    load<kSurface>(*down, p + std::size_t(w));
                    pair<kSurface>(*cur, *down, rayP, 0.0f, 1.0f, kDown, kUp);
                }
                curLoaded = false;
                if (x + 1 < w && m_stack.layerCount(p + 1) != 0) {
                    load<kSurface>(*next, p + 1);
                    pair<kSurface>(*cur, *next, rayP, 1.0f, 0.0f, kRight, kLeft);
                    std::swap(cur, next);
                    curLoaded = true;
                }
            }
        }
    }

    template <bool kSurface> void load(Side& side, std::size_t pixel) {
        side.first = m_stack.offsets[pixel];
        const std::uint32_t layers = m_stack.layerCount(pixel);
        m_truncated = m_truncated || layers > kMaxLinkedLayers;
        side.count = std::min(layers, kMaxLinkedLayers);
        const float* depth = m_stack.depth.data() + side.first;
        if constexpr (kSurface) {
            const std::uint32_t* triangle = m_stack.triangle.data() + side.first;
            const std::uint32_t* entries = m_fragmentEntry ? m_fragmentEntry + side.first : nullptr;
            // Depths copied in this loop: most pixels hold one or two fragments, for which a
            // call of memcpy costs more than the copy.
            for (std::uint32_t k = 0; k < side.count; ++k) {
                side.depth[k] = depth[k];
                side.triangle[k] = triangle[k];
                const SurfaceTriangle* info =
                    entries ? m_geometry->atEntry(entries[k]) : m_geometry->find(triangle[k]);
                side.info[k] = info;
                side.component[k] = info ? info->component : kNone;
            }
            side.packed = false;
        } else {
            std::copy_n(depth, side.count, side.depth);
        }
    }

    /**
     * The ray through one window position, set on first use: most pairs need only the midpoint
     * ray (their depths there decide), the pixels' own rays only for the crease and arc tests.
     */
    class LazyRay {
    public:
        LazyRay(const PixelRays4& rays, float x, float y) : m_rays(rays), m_x(x), m_y(y) {}
        const Ray& get() {
            if (!m_set) {
                setRay(m_rays, m_x, m_y, m_ray);
                m_set = true;
            }
            return m_ray;
        }
        float x() const { return m_x; }
        float y() const { return m_y; }

    private:
        const PixelRays4& m_rays;
        float m_x, m_y;
        bool m_set = false;
        Ray m_ray{};
    };

    /** The rays of one pixel pair: P's and Q's (made on first use) and their midpoint's. */
    struct PairRays {
        LazyRay& p;
        LazyRay q;
        Ray m;
    };

    /**
     * Error of joining fragment i of a (at P) with fragment j of b (at Q); kFail when the test
     * fails. Symmetric in (a, i) and (b, j) up to swapping P and Q.
     */
    [[gnu::always_inline]] float score(const Side& a, std::uint32_t i, const Side& b,
                                       std::uint32_t j, PairRays& rays) {
        const SurfaceTriangle* ta = a.info[i];
        const SurfaceTriangle* tb = b.info[j];
        if (ta && tb) {
            if (a.triangle[i] == b.triangle[j])
                return -1.0f; // same plane: exact at any slope
            const float za = m_midA.get(a, i, rays.m, m_stamp);
            const float zb = m_midB.get(b, j, rays.m, m_stamp);
            if (!std::isnan(za) && !std::isnan(zb)) { // neither grazing
                const float error = std::abs(za - zb);
                if (ta->component != tb->component)
                    return error < m_contactLimit ? error : kFail;
                if (error < m_limit)
                    return error;
                const float cosine = glm::dot(glm::vec3(ta->plane), glm::vec3(tb->plane));
                const bool corner = shareCorner(*ta, *tb);
                const bool crease = corner && cosine >= m_creaseCos;
                const bool facet = corner && cosine >= kFacetCosine;
                const bool smooth = cosine >= m_smoothCos;
                if (crease || smooth) {
                    // The planes' depth difference along P→Q keeps its sign except at one
                    // point (1/depth is affine on screen), so a sign change means their line of
                    // intersection passes between the pixel centres.
                    const float bAtP = m_atP.get(b, j, rays.p.get(), m_stamp);
                    const float aAtQ = m_atQ.get(a, i, rays.q.get(), m_stamp);
                    const bool cross = bAtP > 0.0f && aAtQ > 0.0f &&
                                       (a.depth[i] - bAtP) * (aAtQ - b.depth[j]) <= 0.0f;
                    if (crease && cross)
                        return 0.0f; // the crease through the shared corner is between them
                    if (smooth && cross && !facet) {
                        const float arc = arcError(a, i, b, j, rays, cosine, kArcSlack);
                        if (arc != kFail)
                            return arc;
                    }
                }
                if (facet) {
                    // Facets around a shared corner of a coarse mesh: their planes meet at the
                    // corner, not between the pixels, and one sample lies off the other's
                    // plane by up to about twice the arc's distance; a fold this flat would
                    // be off by four times or more.
                    const float arc = arcError(a, i, b, j, rays, cosine, kFacetSlack);
                    if (arc != kFail)
                        return arc;
                }
                return kFail;
            }
        }
        // Plain test: grazing, degenerate or unknown triangles.
        const float error = std::abs(a.depth[i] - b.depth[j]);
        const bool differentParts = ta && tb && ta->component != tb->component;
        if (error < (differentParts ? m_contactLimit : m_limit))
            return error;
        // Seen edge-on, one mesh part may still continue smoothly (a silhouette pixel).
        if (ta && tb && !differentParts) {
            const float cosine = glm::dot(glm::vec3(ta->plane), glm::vec3(tb->plane));
            if (cosine >= m_smoothCos && ta->plane != glm::vec4(0.0f) &&
                tb->plane != glm::vec4(0.0f))
                return arcError(a, i, b, j, rays, cosine, kArcSlack);
        }
        return kFail;
    }

    /** What deepScores() finds for a group of kLanes fragment pairs. */
    struct Scores {
        IntsN known;   // lanes whose score is known: the score, or failing
        FloatsN score; // of the known lanes; kFail when they fail
    };

    /**
     * score() (and contactScore()) of a's fragment i with b's fragments j0 to j0 + kLanes - 1, from
     * the plane depths pair() computed for all fragments of two deep pixels, for the lanes where
     * these decide: the two share a triangle, their depths on the midpoint ray are within the
     * threshold (of one mesh part) or the contact limit (of two), or no crease, arc or facet
     * test could join them. Lanes with a plane depth unknown (grazing, degenerate, no triangle)
     * or a test to run are left to score(). Exactly score()'s arithmetic, kLanes at a time.
     */
    Scores deepScores(const Side& a, std::uint32_t i, const Side& b, std::uint32_t j0) const {
        const FloatsN error = absN(m_midA.value[i] - loadLanes<FloatsN>(m_midB.value + j0));
        const IntsN valid = error == error; // not NaN: both plane depths known
        const IntsN sameTriangle = loadLanes<IntsN>(b.triangle + j0) == std::int32_t(a.triangle[i]);
        const IntsN samePart = loadLanes<IntsN>(b.component + j0) == std::int32_t(a.component[i]);
        const IntsN near = (samePart & (error < m_limit)) | (~samePart & (error < m_contactLimit));
        const FloatsN fail = FloatsN{} + kFail, same = FloatsN{} - 1.0f;
        const FloatsN score = selectN(sameTriangle, same, selectN(near, error, fail));
        // Beyond the threshold, within one part: a crease (shared corner, planes crossing
        // between the pixels), an arc (planes crossing) or a facet (shared corner) may join.
        const IntsN beyond = valid & samePart & ~sameTriangle & ~near;
        if (bitsN(beyond) == 0)
            return {valid, score};
        const FloatsN cosine = a.plane[0][i] * loadLanes<FloatsN>(b.plane[0] + j0) +
                               a.plane[1][i] * loadLanes<FloatsN>(b.plane[1] + j0) +
                               a.plane[2][i] * loadLanes<FloatsN>(b.plane[2] + j0);
        const FloatsN bAtP = loadLanes<FloatsN>(m_atP.value + j0);
        const float aAtQ = m_atQ.value[i];
        const IntsN cross =
            (bAtP > 0.0f) & (IntsN{} - (aAtQ > 0.0f ? 1 : 0)) &
            ((a.depth[i] - bAtP) * (aAtQ - loadLanes<FloatsN>(b.depth + j0)) <= 0.0f);
        const IntsN smooth = cross & (cosine >= m_smoothCos);
        // Lanes where a shared corner would decide (a crease, a facet), of those whose corner
        // bits meet (all that share a corner, and a few more).
        const IntsN cornerCounts =
            beyond & ~smooth &
            ((loadLanes<IntsN>(b.cornerBits + j0) & std::int32_t(a.cornerBits[i])) != 0) &
            ((cross & (cosine >= m_creaseCos)) | (cosine >= kFacetCosine));
        IntsN corner{};
        if (bitsN(cornerCounts) != 0) {
            for (int c = 0; c < 3; ++c) {
                const IntsN other = loadLanes<IntsN>(b.corner[c] + j0);
                for (int d = 0; d < 3; ++d)
                    corner |= other == std::int32_t(a.corner[d][i]);
            }
            corner &= loadLanes<IntsN>(b.corner[0] + j0) != std::int32_t(kNone);
        }
        const IntsN tests = beyond & (smooth | (corner & cornerCounts));
        return {valid & ~tests, score};
    }

    /** score() for fragments with known triangles of different mesh parts. */
    float contactScore(const Side& a, std::uint32_t i, const Side& b, std::uint32_t j,
                       PairRays& rays) {
        const float za = m_midA.get(a, i, rays.m, m_stamp);
        const float zb = m_midB.get(b, j, rays.m, m_stamp);
        const float error = !std::isnan(za) && !std::isnan(zb) ? std::abs(za - zb)
                                                               : std::abs(a.depth[i] - b.depth[j]);
        return error < m_contactLimit ? error : kFail;
    }

    /**
     * For a smooth surface curving between the two samples (one mesh part, triangles not
     * adjacent, as where triangles are smaller than pixels or near silhouettes, where the depth
     * prediction over half a pixel is poor): the samples must lie on a common arc, i.e. each
     * sample's distance from the other's plane is at most about chord × sin(half the normal
     * angle). Two unrelated sheets fail by a factor of about 2 even when one is seen edge-on, and
     * parallel sheets by their gap. Returns the larger distance, or kFail.
     */
    float arcError(const Side& a, std::uint32_t i, const Side& b, std::uint32_t j, PairRays& rays,
                   float cosine, float slack) const {
        const glm::vec4& planeA = a.info[i]->plane;
        const glm::vec4& planeB = b.info[j]->plane;
        const Ray& p = rays.p.get();
        const Ray& q = rays.q.get();
        const glm::vec3 pointA = p.origin + a.depth[i] * p.direction;
        const glm::vec3 pointB = q.origin + b.depth[j] * q.direction;
        const float chord = glm::length(pointB - pointA);
        const float sinHalf = std::sqrt(std::max(0.0f, 0.5f * (1.0f - cosine)));
        const float bound = slack * chord * sinHalf + m_limit;
        const float fromA = std::abs(glm::dot(glm::vec3(planeA), pointB) + planeA.w);
        const float fromB = std::abs(glm::dot(glm::vec3(planeB), pointA) + planeB.w);
        return fromA <= bound && fromB <= bound ? std::max(fromA, fromB) : kFail;
    }

    /** Whether the triangles share a welded corner, so their planes meet at a mesh point. */
    static bool shareCorner(const SurfaceTriangle& a, const SurfaceTriangle& b) {
        if (a.corners[0] == kNone || b.corners[0] == kNone)
            return false;
        for (std::uint32_t v : a.corners)
            if (v == b.corners[0] || v == b.corners[1] || v == b.corners[2])
                return true;
        return false;
    }

    /** True when candidate layer c (score s) beats the current best for a fragment on layer
     * self: lower score, then the same layer, then the shallower layer. */
    static bool better(float s, std::uint32_t c, float bestScore, std::uint32_t best,
                       std::uint32_t self) {
        if (s != bestScore)
            return s < bestScore;
        const std::uint32_t rankC = c == self ? 0 : c, rankBest = best == self ? 0 : best;
        return rankC < rankBest;
    }

    template <bool kSurface>
    void pair(Side& a, Side& b, LazyRay& rayP, float dx, float dy, int forward, int backward) {
        std::uint8_t* links = m_out.links.data();
        const bool single = a.count == 1 && b.count == 1;
        if constexpr (kSurface) {
            // One fragment each of one triangle: score() joins them without the rays.
            if (single && a.info[0] && b.info[0] && a.triangle[0] == b.triangle[0]) {
                links[4 * std::size_t(a.first) + std::size_t(forward)] = 1;
                links[4 * std::size_t(b.first) + std::size_t(backward)] = 1;
                return;
            }
        }
        const float px = rayP.x(), py = rayP.y();
        PairRays rays{rayP, LazyRay(m_rays, px + dx, py + dy), {}};
        if constexpr (kSurface) {
            setRay(m_rays, px + 0.5f * dx, py + 0.5f * dy, rays.m);
            if (++m_stamp == 0) { // wrapped: forget every stamp
                for (LazyDepths* lazy : {&m_midA, &m_midB, &m_atP, &m_atQ}) {
                    std::fill_n(lazy->stamp, kMaxLinkedLayers, 0u);
                    lazy->all = 0;
                }
                m_stamp = 1;
            }
        }
        if constexpr (kSurface) {
            if (a.count * b.count >= m_deepPair) {
                deepPair(a, b, rays, forward, backward);
                return;
            }
            if (single) {
                // One fragment each (most pairs of a shallow view): they are each other's best
                // partner exactly when the pair does not fail.
                const float s = a.info[0] && b.info[0] && a.component[0] != b.component[0]
                                    ? contactScore(a, 0, b, 0, rays)
                                    : score(a, 0, b, 0, rays);
                const std::uint8_t linked = s < kFail ? 1 : 0;
                links[4 * std::size_t(a.first) + std::size_t(forward)] = linked;
                links[4 * std::size_t(b.first) + std::size_t(backward)] = linked;
                return;
            }
        }
        link(a, b, forward, backward, [&](std::uint32_t i, auto&& take) {
            for (std::uint32_t j = 0; j < b.count; ++j) {
                if constexpr (kSurface) {
                    // Fragments of different mesh parts (most pairs in a deep pixel) join only
                    // where they touch: score()'s contact test, without its other loads.
                    if (a.info[i] && b.info[j] && a.component[i] != b.component[j])
                        take(j, contactScore(a, i, b, j, rays));
                    else
                        take(j, score(a, i, b, j, rays));
                } else
                    take(j, plainScore(a.depth[i], b.depth[j]));
            }
        });
    }

    /**
     * pair() for two deep pixels: every plane depth the tests read, kLanes fragments at a time,
     * then deepScores() for all fragment pairs, kLanes at a time; score() only for what it
     * leaves.
     */
    [[gnu::noinline]] void deepPair(Side& a, Side& b, PairRays& rays, int forward, int backward) {
        pack(a);
        pack(b);
        fill(m_midA, a, rays.m);
        fill(m_midB, b, rays.m);
        fill(m_atQ, a, rays.q.get());
        fill(m_atP, b, rays.p.get());
        link(a, b, forward, backward,
             [&](std::uint32_t i, auto&& take) { deepRow(a, i, b, rays, take); });
    }

    /** deepPair()'s scores of a's fragment i with each of b's, given to take(j, score). */
    template <typename Take>
    void deepRow(const Side& a, std::uint32_t i, const Side& b, PairRays& rays, Take& take) {
        for (std::uint32_t j0 = 0; j0 < b.count; j0 += kLanes) {
            const Scores known = deepScores(a, i, b, j0);
            const unsigned inside = lanesOf(b.count, j0);
            for (unsigned joins = bitsN(known.known & (known.score != kFail)) & inside; joins != 0;
                 joins &= joins - 1) {
                const unsigned k = unsigned(std::countr_zero(joins));
                take(j0 + k, known.score[k]);
            }
            for (unsigned rest = bitsN(~known.known) & inside; rest != 0; rest &= rest - 1) {
                const std::uint32_t j = j0 + unsigned(std::countr_zero(rest));
                take(j, a.info[i] && b.info[j] && a.component[i] != b.component[j]
                            ? contactScore(a, i, b, j, rays)
                            : score(a, i, b, j, rays));
            }
        }
    }

    /**
     * Writes the links between the fragments of a and b: each fragment's best partner by
     * (score, rank), among the pairs for which scores(i, take) calls take(j, score) (at most
     * once each; pairs not taken fail). The order does not matter.
     */
    template <typename Scores>
    [[gnu::always_inline]] void link(const Side& a, const Side& b, int forward, int backward,
                                     Scores&& scores) {
        float bestForB[kMaxLinkedLayers];
        std::uint32_t choiceForB[kMaxLinkedLayers];
        std::fill_n(bestForB, b.count, kFail);
        std::fill_n(choiceForB, b.count, 0u);
        std::uint8_t* links = m_out.links.data();
        for (std::uint32_t i = 0; i < a.count; ++i) {
            float bestScore = kFail;
            std::uint32_t best = 0;
            scores(i, [&](std::uint32_t j, float s) {
                if (s == kFail)
                    return;
                if (better(s, j + 1, bestScore, best, i + 1)) {
                    bestScore = s;
                    best = j + 1;
                }
                if (better(s, i + 1, bestForB[j], choiceForB[j], j + 1)) {
                    bestForB[j] = s;
                    choiceForB[j] = i + 1;
                }
            });
            links[4 * std::size_t(a.first + i) + std::size_t(forward)] = std::uint8_t(best);
        }
        for (std::uint32_t j = 0; j < b.count; ++j)
            links[4 * std::size_t(b.first + j) + std::size_t(backward)] =
                std::uint8_t(choiceForB[j]);
    }

    /** Copies the planes and corners of side's fragments into its arrays, once per load. */
    static void pack(Side& side) {
        if (side.packed)
            return;
        side.packed = true;
        static const SurfaceTriangle unknown{}; // a zero plane, no corners
        for (std::uint32_t k = 0; k < side.count; ++k) {
            const SurfaceTriangle& info = side.info[k] ? *side.info[k] : unknown;
            for (int c = 0; c < 4; ++c)
                side.plane[c][k] = info.plane[c];
            const auto& corners = info.corners;
            for (int c = 0; c < 3; ++c)
                side.corner[c][k] = corners[std::size_t(c)];
            side.cornerBits[k] =
                corners[0] != kNone
                    ? cornerBit(corners[0]) | cornerBit(corners[1]) | cornerBit(corners[2])
                    : 0u;
        }
    }

    /**
     * Computes lazy's depths of all of side's fragments on ray: planeDepth(), kLanes at a time (a
     * fragment without a triangle has a zero plane, which gives NaN as a grazing one does).
     */
    void fill(LazyDepths& lazy, const Side& side, const Ray& ray) const {
        const float minDenom2 = kMinRayCosine * kMinRayCosine * ray.length2;
        const FloatsN nan = FloatsN{} + std::numeric_limits<float>::quiet_NaN();
        for (std::uint32_t k = 0; k < side.count; k += kLanes) {
            const FloatsN x = loadLanes<FloatsN>(side.plane[0] + k);
            const FloatsN y = loadLanes<FloatsN>(side.plane[1] + k);
            const FloatsN z = loadLanes<FloatsN>(side.plane[2] + k);
            const FloatsN w = loadLanes<FloatsN>(side.plane[3] + k);
            const FloatsN denom = x * ray.direction.x + y * ray.direction.y + z * ray.direction.z;
            const FloatsN depth =
                -(w + x * ray.origin.x + y * ray.origin.y + z * ray.origin.z) / denom;
            const FloatsN value = selectN(denom * denom >= minDenom2, depth, nan);
            std::memcpy(lazy.value + k, &value, sizeof value);
        }
        lazy.all = m_stamp;
    }

    float plainScore(float za, float zb) const {
        const float error = std::abs(za - zb);
        return error < m_limit ? error : kFail;
    }

    const DepthStack& m_stack;
    const SurfaceGeometry* m_geometry;
    PixelRays4 m_rays;                              // m_geometry's rays (or the default ones)
    const std::uint32_t* m_fragmentEntry = nullptr; // SurfaceGeometry::fragmentEntry, if made
    Connectivity& m_out;
    bool m_truncated = false;
    float m_limit = 0.0f;
    float m_contactLimit = 0.0f;
    float m_creaseCos = 0.0f;
    float m_smoothCos = 1.0f;
    std::uint32_t m_deepPair = kDeepPair; // fragment pairs from which pair() takes deepPair()
    Side m_sides[3];
    // Plane depths of a's and b's fragments on the midpoint ray, of b's on P's ray, of a's on Q's.
    LazyDepths m_midA, m_midB, m_atP, m_atQ;
    std::uint32_t m_stamp = 0;
};

/**
 * Links bands of kRowsPerChunk rows, each the next one that no thread has taken (next counts
 * them), until all chunks bands are done. Returns whether a pixel had more than
 * kMaxLinkedLayers fragments.
 */
bool linkBands(const DepthStack& stack, const ConnectivityOptions& options,
               const SurfaceGeometry* geometry, Connectivity& out, std::atomic<int>& next,
               int chunks) {
    auto linker = std::make_unique<Linker>(stack, options, geometry, out);
    for (int chunk = next.fetch_add(1); chunk < chunks; chunk = next.fetch_add(1))
        linker->rows(chunk * kRowsPerChunk, std::min(stack.height, (chunk + 1) * kRowsPerChunk));
    return linker->truncated();
}

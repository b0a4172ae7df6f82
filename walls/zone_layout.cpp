#include "walls/zone_layout.h"

#include "walls/parallel_for.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace cavewall::walls {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMinPieceArea = 1e-8;             // m²; slivers from clipping are dropped
constexpr double kNearerSampling[] = {0.75, 0.5};  // share of the core kept, nearest the wall
constexpr double kMaxBorderTries = 32;             // geometry borders tried after the first
constexpr double kCutPrecision = 1e-3;             // metres: column borders of the planned rows

struct Row {
    double a = 0, b = 0;
    double dLo = 0, dHi = 0;          // the extended (validated) depth range
    std::vector<double> cuts;         // column borders (s)
    std::vector<glm::dvec3> samples;  // one per column
};

struct Context {
    const SideInput& in;
    Polygon2 cell;  // local (s, d)
    double alpha, blend, minSize;
    double sLo, sHi, dMin, dMax;
    const PlanOptions* options = nullptr;
    glm::dvec2 span{0.0, kInf};  // the wall's depth span (depth walls)
    bool flatBound = false;      // prove with the flat bound whatever the wall kind

    // Is the volume proven within alpha for the texture baked from `sample`?
    bool proven(const ZoneVolume& volume, glm::dvec3 sample) const {
        if (flatBound || options->wallKind == WallKind::Flat) return zoneWithin(volume, sample, in.quad, alpha);
        return depthTextureWithin(volume, sample, in.quad, span, *options, alpha);
    }

    Polygon2 world(const Polygon2& local) const {
        Polygon2 out;
        for (const glm::dvec2& p : local) out.push_back(in.frame.toWorld(p));
        return out;
    }
    glm::dvec3 sampling(const Polygon2& local) const {
        const glm::dvec2 w = in.frame.toWorld(centroid(local));
        return {w.x, 0.5 * (in.heightRange.x + in.heightRange.y), w.y};
    }
    // Is the column [left, right] of the row valid (proven within alpha over its extension)?
    bool valid(const Row& row, double left, double right, glm::dvec3* sample) const {
        const Polygon2 core = clipBox(cell, {left, row.a}, {right, row.b});
        const Polygon2 ext = clipBox(cell, {left - 0.5 * blend, row.dLo}, {right + 0.5 * blend, row.dHi});
        *sample = sampling(core.empty() ? (ext.empty() ? cell : ext) : core);
        if (ext.empty()) return true;
        const ZoneVolume volume{world(ext), in.heightRange};
        if (proven(volume, *sample)) return true;
        // Eyes near the wall dominate the error: a sampling point nearer the wall's side of
        // the zone often serves the whole zone when the centroid does not.
        for (double f : kNearerSampling) {
            const double d = glm::dot(in.frame.toLocal({sample->x, sample->z}), glm::dvec2(0, 1));
            const Polygon2 nearer =
                clipBox(core.empty() ? ext : core, {-kInf, -kInf}, {kInf, row.a + f * (d - row.a) * 2});
            if (nearer.empty()) continue;
            const glm::dvec3 s = sampling(nearer);
            if (proven(volume, s)) return *sample = s, true;
        }
        return false;
    }
};

void extentOf(const Polygon2& p, glm::dvec2& lo, glm::dvec2& hi) {
    lo = glm::dvec2(kInf);
    hi = glm::dvec2(-kInf);
    for (const glm::dvec2& v : p) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
}

// Greedy columns of maximal width: from the previous column's width, doubled while valid, then
// bisected to `precision` metres; nullopt when it leaves a remainder that is neither valid
// whole nor splittable into columns of minZoneSize. Starting from the previous width (widths
// change slowly along a row) makes a column cost a few checks more than log2(width /
// precision), not log2(row width / precision): a 2 km row no longer costs 21 checks a column.
std::optional<Row> greedyColumns(const Context& c, Row row, double sLo, double sHi, double precision) {
    double left = -kInf, leftPos = sLo, width = c.minSize;
    for (;;) {
        glm::dvec3 sample;
        if (c.valid(row, left, kInf, &sample)) {
            row.samples.push_back(sample);
            return row;
        }
        double good = leftPos + c.minSize, bad = sHi - c.minSize;
        glm::dvec3 goodSample, trial;
        if (good > bad || !c.valid(row, left, good, &goodSample)) return std::nullopt;
        for (double step = width;; step *= 2) {
            const double probe = leftPos + step;
            if (probe <= good) continue;
            if (probe >= bad) {
                if (c.valid(row, left, bad, &trial)) {
                    good = bad;
                    goodSample = trial;
                }
                break;
            }
            if (!c.valid(row, left, probe, &trial)) {
                bad = probe;
                break;
            }
            good = probe;
            goodSample = trial;
        }
        while (bad - good > precision) {
            const double mid = 0.5 * (good + bad);
            if (c.valid(row, left, mid, &trial)) {
                good = mid;
                goodSample = trial;
            } else
                bad = mid;
        }
        row.cuts.push_back(good);
        row.samples.push_back(goodSample);
        width = good - leftPos;
        left = leftPos = good;
    }
}

// n columns of equal width; nullopt when one of them is not valid.
std::optional<Row> equalColumns(const Context& c, Row row, double sLo, double sHi, int n) {
    for (int k = 1; k < n; ++k) row.cuts.push_back(sLo + (sHi - sLo) * k / n);
    for (int k = 0; k < n; ++k) {
        glm::dvec3 sample;
        if (!c.valid(row, k == 0 ? -kInf : row.cuts[k - 1], k + 1 == n ? kInf : row.cuts[k], &sample))
            return std::nullopt;
        row.samples.push_back(sample);
    }
    return row;
}

// The row's columns: greedy widths, or when the greedy cut leaves an unusable remainder, the
// fewest equal columns that are all valid.
std::optional<Row> planRow(const Context& c, const Row& row, double precision = kCutPrecision) {
    const Polygon2 band = clipBox(c.cell, {-kInf, row.a}, {kInf, row.b});
    glm::dvec2 lo, hi;
    extentOf(band, lo, hi);
    if (band.empty()) lo.x = hi.x = 0;
    if (auto greedy = greedyColumns(c, row, lo.x, hi.x, precision)) return greedy;
    // Counts grow by a quarter from 8 on, so a wide cell costs O(columns) checks, not O(columns²).
    const double most = std::floor((hi.x - lo.x) / c.minSize);
    for (int n = 2; n <= most; n = n < 8 ? n + 1 : n + n / 4)
        if (auto equal = equalColumns(c, row, lo.x, hi.x, n)) return equal;
    return std::nullopt;
}

Row makeRow(const Context& c, double a, double b, bool geometryBelow, bool first) {
    Row r;
    r.a = a;
    r.b = b;
    r.dLo = first ? (geometryBelow ? a : -kInf) : a - 0.5 * c.blend;
    r.dHi = b >= c.dMax ? kInf : b + 0.5 * c.blend;
    return r;
}

// Rows from `start` to dMax; each row's depth is the candidate covering the most depth per
// texture (candidates minSize * 2^k, planned in parallel; ties go to the deeper row).
std::optional<std::vector<Row>> planRows(const Context& c, double start, bool geometryBelow) {
    std::vector<Row> rows;
    for (double a = start; a < c.dMax;) {
        std::vector<double> ends;
        for (double extent = c.minSize;; extent *= 2) {
            double b = std::min(c.dMax, a + extent);
            if (c.dMax - b < c.minSize) b = c.dMax;
            ends.push_back(b);
            if (b >= c.dMax) break;
        }
        std::vector<std::optional<Row>> candidates(ends.size());
        parallelFor(int(ends.size()),
                    [&](int i) { candidates[i] = planRow(c, makeRow(c, a, ends[i], geometryBelow, rows.empty())); });
        std::optional<Row> best;
        double bestScore = -1;
        for (std::size_t i = 0; i < ends.size(); ++i) {
            const double score = candidates[i] ? (ends[i] - a) / double(candidates[i]->samples.size()) : -1;
            if (candidates[i] && score >= bestScore) {
                best = std::move(candidates[i]);
                bestScore = score;
            }
        }
        if (!best) return std::nullopt;
        rows.push_back(*best);
        a = best->b;
    }
    return rows;
}

// Only feasibility counts here, so column borders are bisected to a tenth of minZoneSize, not
// to kCutPrecision (a border search plans this row about twenty times).
bool firstRowFeasible(const Context& c, double d) {
    const double b = c.dMax - d < 2 * c.minSize ? c.dMax : d + c.minSize;
    return planRow(c, makeRow(c, d, b, true, true), std::max(kCutPrecision, 0.1 * c.minSize)).has_value();
}

struct Layout {
    bool geometryBelow = false;
    double dG = 0;
    std::vector<Row> rows;  // empty: the whole cell is geometry
};

Layout layout(const Context& c) {
    // Depth walls keep the geometry strip the flat bound needs (plan.h): their own bound would
    // prove zones nearer the wall, which then need many large textures. The flat layout's rows
    // are planned only to find that border (about 0.5 s on the default plant).
    double from = c.dMin;
    if (c.options->wallKind == WallKind::Depth && !c.flatBound) {
        Context flat = c;
        flat.flatBound = true;
        const Layout f = layout(flat);
        if (f.geometryBelow) from = f.dG;
    }
    if (from <= c.dMin)
        if (auto rows = planRows(c, c.dMin, false)) return {false, c.dMin, *rows};
    double lo = from, hi = std::max(from, c.dMax - c.minSize);
    if (!firstRowFeasible(c, hi)) return {true, c.dMax, {}};
    if (from > c.dMin && firstRowFeasible(c, from)) hi = from;
    while (hi - lo > 1e-3) {
        const double mid = 0.5 * (lo + hi);
        (firstRowFeasible(c, mid) ? hi : lo) = mid;
    }
    // Validity is not strictly monotone in d; move the geometry border outwards until the
    // rows close (at worst the whole cell becomes geometry). At most kMaxBorderTries steps,
    // so a deep cell does not replan its rows thousands of times.
    const double step = std::max(c.minSize, (c.dMax - hi) / kMaxBorderTries);
    for (double dG = hi; dG < c.dMax; dG += step)
        if (auto rows = planRows(c, dG, true)) return {true, dG, *rows};
    return {true, c.dMax, {}};
}

struct Emitter {
    const Context& c;
    Plan& plan;
    std::vector<Zone>& zones;
    const std::vector<Row>& rows;
    std::vector<std::vector<int>> textureIds;  // [row][column]

    void zone(ZoneKind kind, const Polygon2& local, std::vector<int> textures, bool mixesGeometry) {
        if (local.empty() || std::abs(signedArea(local)) < kMinPieceArea) return;
        Zone z;
        z.id = int(zones.size());
        z.cell = c.in.cell;
        z.wall = c.in.wall;
        z.kind = kind;
        z.floorPolygon = c.world(local);
        z.heightRange = c.in.heightRange;
        z.textures = std::move(textures);
        z.mixesGeometry = mixesGeometry;
        zones.push_back(std::move(z));
    }
    // The column interval of row r, column k, widened by `grow` on interior borders.
    glm::dvec2 column(const Row& r, std::size_t k, double grow) const {
        return {k == 0 ? -kInf : r.cuts[k - 1] - grow, k == r.cuts.size() ? kInf : r.cuts[k] + grow};
    }
    // Cuts the depth band [d0, d1] at every column border +- blend/2 of the rows `which`; each piece mixes
    // the textures whose validated columns contain it.
    void band(double d0, double d1, const std::vector<int>& which, bool mixesGeometry) {
        std::vector<double> breaks;
        for (int r : which)
            for (double cut : rows[r].cuts) breaks.insert(breaks.end(), {cut - 0.5 * c.blend, cut + 0.5 * c.blend});
        std::sort(breaks.begin(), breaks.end());
        breaks.insert(breaks.begin(), -kInf);
        breaks.push_back(kInf);
        for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
            const double p = breaks[i], q = breaks[i + 1];
            if (!(q > p)) continue;
            std::vector<int> textures;
            for (int r : which)
                for (std::size_t k = 0; k <= rows[r].cuts.size(); ++k) {
                    const glm::dvec2 col = column(rows[r], k, 0.5 * c.blend);
                    if (col.x <= p && q <= col.y) textures.push_back(textureIds[r][k]);
                }
            const ZoneKind kind = mixesGeometry || textures.size() > 1 ? ZoneKind::Blend : ZoneKind::Texture;
            zone(kind, clipBox(c.cell, {p, d0}, {q, d1}), std::move(textures), mixesGeometry);
        }
    }
    // Adds the textures of row r (one per column) and returns the row's public description.
    PlannedRow textures(int r, int& count) {
        const Row& row = rows[r];
        textureIds.emplace_back();
        for (std::size_t k = 0; k < row.samples.size(); ++k) {
            Texture t;
            t.id = int(plan.textures.size());
            t.cell = c.in.cell;
            t.wall = c.in.wall;
            t.samplingPoint = row.samples[k];
            const glm::dvec2 col = column(row, k, 0.5 * c.blend);
            t.validRegion = c.world(clipBox(c.cell, {col.x, row.dLo}, {col.y, row.dHi}));
            textureIds.back().push_back(t.id);
            plan.textures.push_back(std::move(t));
            ++count;
        }
        return {row.a, row.b, {row.dLo, row.dHi}, row.cuts, textureIds.back()};
    }
};

Context contextOf(const Plan& plan, const SideInput& in) {
    Context c{in, {}, glm::radians(plan.options.alphaDeg), plan.options.blendWidth, plan.options.minZoneSize, 0, 0,
              0,  0};
    c.options = &plan.options;
    c.span = {plan.walls[in.wall].depthNear, plan.walls[in.wall].depthBehind};
    for (const glm::dvec2& p : in.cellRegion) c.cell.push_back(in.frame.toLocal(p));
    glm::dvec2 lo, hi;
    extentOf(c.cell, lo, hi);
    c.sLo = lo.x;
    c.sHi = hi.x;
    c.dMin = lo.y;
    c.dMax = hi.y;
    return c;
}

// Numbers the layout's textures and zones after those already in `plan` and `zones`.
WallSide emit(Plan& plan, const Context& c, const Layout& l, std::vector<Zone>& zones) {
    const SideInput& in = c.in;
    WallSide side;
    side.cell = in.cell;
    side.wall = in.wall;
    side.side = in.side;
    side.firstZone = int(zones.size());
    side.origin = in.frame.origin;
    side.along = in.frame.along;
    side.inward = in.frame.inward;
    side.geometryDistance = l.geometryBelow ? l.dG : c.dMin;
    side.hasGeometry = l.geometryBelow;
    Emitter e{c, plan, zones, l.rows, {}};
    for (int r = 0; r < int(l.rows.size()); ++r) side.rows.push_back(e.textures(r, side.textureCount));
    if (l.geometryBelow) e.zone(ZoneKind::Geometry, clipBox(c.cell, {-kInf, -kInf}, {kInf, l.dG}), {}, false);
    const double w = c.blend;
    for (int r = 0; r < int(l.rows.size()); ++r) {
        const Row& row = l.rows[r];
        const bool last = r + 1 == int(l.rows.size());
        double low = r > 0 ? row.a + 0.5 * w : (l.geometryBelow ? row.a + w : -kInf);
        if (r == 0 && l.geometryBelow && w > 0) e.band(row.a, row.a + w, {0}, true);
        e.band(low, last ? kInf : row.b - 0.5 * w, {r}, false);
        if (!last && w > 0) e.band(row.b - 0.5 * w, row.b + 0.5 * w, {r, r + 1}, false);
    }
    side.zoneCount = int(zones.size()) - side.firstZone;
    return side;
}

}  // namespace

WallSide planSide(Plan& plan, const SideInput& in, std::vector<Zone>& zones) {
    const Context c = contextOf(plan, in);
    return emit(plan, c, layout(c), zones);
}

std::vector<WallSide> planSides(Plan& plan, const std::vector<SideInput>& inputs, std::vector<Zone>& zones) {
    // A layout reads only the options and its wall's depth span; numbering waits for all of
    // them so ids follow the inputs' order whatever the threads' timing.
    std::vector<Context> contexts;
    contexts.reserve(inputs.size());
    for (const SideInput& in : inputs) contexts.push_back(contextOf(plan, in));
    std::vector<Layout> layouts(inputs.size());
    parallelFor(int(inputs.size()), [&](int i) { layouts[i] = layout(contexts[i]); });
    std::vector<WallSide> sides;
    sides.reserve(inputs.size());
    for (std::size_t i = 0; i < inputs.size(); ++i) sides.push_back(emit(plan, contexts[i], layouts[i], zones));
    return sides;
}

}  // namespace cavewall::walls

#include "walkthrough/frame_planner.h"

#include "display/pixel_scale.h"
#include "display/warp.h"
#include "scenes/region.h"
#include "walls/angular_error.h"

#include <algorithm>
#include <array>
#include <cassert>

namespace cavewall::walkthrough {

namespace {

// What a wall drew last (Transition::Warp): a switch between the two starts a warp-morph.
enum class Look { Nothing, Geometry, Texture };

using TextureSet = std::vector<std::pair<int, double>>;

// Transition::Warp: a blend of textures and geometry becomes whichever has the larger weight
// (the warp-morph replaces the fade); textures keep their relative weights.
walls::WallBlend binaryBlend(walls::WallBlend b) {
    if (b.textures.empty() || b.geometryWeight <= 0.0 || b.geometryWeight >= 1.0) return b;
    if (b.geometryWeight >= 0.5) {
        b.textures.clear();
    } else {
        for (auto& [id, weight] : b.textures) weight /= 1.0 - b.geometryWeight;
    }
    b.geometryWeight = b.textures.empty() ? 1.0 : 0.0;
    return b;
}

void setCell(std::vector<bool>& cells, int cell, bool value) {
    if (cell >= 0 && cell < static_cast<int>(cells.size())) cells[cell] = value;
}

}  // namespace

// Per wall, across frames.
struct FramePlanner::Memory {
    int lastSide = 0;           // the side and textures drawn last; reused only
    TextureSet lastTextures;    // from the same side
    Look look = Look::Nothing;  // Transition::Warp: what it drew last
    std::optional<glm::dvec3> lastSamplingPoint;
    MorphPhase phase = MorphPhase::Idle;
    double start = 0.0;             // FrameInput::time of the switch
    glm::dvec3 samplingPoint{0.0};  // the texture's end of the morph
};

// What the warp does to one wall this frame.
struct FramePlanner::WarpOutcome {
    enum class Kind {
        None,      // drawn as chosen, nothing warped
        Warp,      // drawn as chosen, structure behind warped into its texture
        Morph,     // no quad: its cell behind drawn warped from the morph's viewpoint
        Fallback,  // ill-conditioned warp: drawn as geometry
    };
    Kind kind = Kind::None;
    walls::WarpWall warp;
    MorphPhase phase = MorphPhase::Idle;
    double share = 0.0;
};

FramePlanner::FramePlanner(const scenes::Scene& scene, const scenes::SceneDescription& description,
                           const display::Display& display, const walls::WallSetup* walls, Transition transition,
                           double morphSeconds, std::vector<int> screens)
    : _scene(scene), _description(description), _display(display), _walls(walls), _transition(transition),
      _morphSeconds(morphSeconds), _screens(std::move(screens)) {
    assert(morphSeconds > 0.0);
    if (_screens.empty())
        for (int s = 0; s < static_cast<int>(display.screens().size()); ++s) _screens.push_back(s);
    if (!_walls || _walls->plan.walls.empty()) {
        _walls = nullptr;
        return;
    }
    _selector.emplace(_walls->plan, _walls->table, description);
    _portals.emplace(_walls->plan, description, scene);
    for (const walls::Texture& t : _walls->plan.textures) _textures[t.id] = &t;
    _memory.resize(_walls->plan.walls.size());
}

FramePlanner::~FramePlanner() = default;

TextureRequests FramePlanner::requests(const FrameInput& input, const std::vector<display::ScreenView>& views) {
    _input = input;
    _views = views;
    _caveFromWorld = glm::inverse(input.worldFromCave);
    _eye = glm::dvec3(input.worldFromCave * glm::dvec4(input.head.position, 1.0));
    _outOfView.clear();
    _planned = false;
    // The eye's velocity from the last frame's (none on the first frame or after a jump back in time).
    const double dt = input.time - _lastTime;
    glm::dvec3 velocity = _hasLast && dt > 0.0 ? (_eye - _lastEye) / dt : glm::dvec3(0.0);
    velocity.y = 0.0;  // along the floor
    _lastEye = _eye;
    _lastTime = input.time;
    _hasLast = true;
    TextureRequests r;
    if (!_selector) return r;
    _selection = _selector->select(_eye);
    // Where the eye will be if it keeps its velocity, kLookaheadSeconds ahead, at least
    // kNeighbourMetres (the beyond walls have no neighbouring zones of their own) and at most
    // kLookaheadMetres away.
    std::vector<glm::dvec3> ahead;
    const double speed = glm::length(velocity);
    double lastMetres = 0.0;  // clamping can repeat a point; each is selected once
    for (double t : kLookaheadSeconds) {
        const double metres = std::clamp(speed * t, kNeighbourMetres, kLookaheadMetres);
        if (speed > kMovingMetresPerSecond && metres > lastMetres) {
            ahead.push_back(_eye + velocity * (metres / speed));
            lastMetres = metres;
        }
    }
    std::vector<walls::FrameSelection> aheadSelections;
    for (const glm::dvec3& p : ahead) aheadSelections.push_back(_selector->select(p));
    _seen = _selection;
    auto outOfView = [&](const walls::WallBlend& b, bool beyond) {
        if (wallInView(b.wall)) return false;
        _outOfView.push_back(WallState{b.wall, {}, b.geometryWeight, false, beyond});
        return true;
    };
    std::erase_if(_seen.walls, [&](const walls::WallBlend& b) { return outOfView(b, false); });
    std::erase_if(_seen.beyond, [&](const walls::WallBlend& b) { return outOfView(b, true); });
    const glm::dvec2 eye(_eye.x, _eye.z);
    for (const walls::WallBlend& b : _seen.walls) {
        for (const auto& [id, weight] : b.textures) r.now.push_back(id);
        const auto& sides = _walls->plan.sides;
        const auto side = std::find_if(sides.begin(), sides.end(), [&](const walls::WallSide& s) {
            return s.cell == _seen.cell && s.wall == b.wall;
        });
        if (side == sides.end()) continue;
        // Neighbouring zones: what the selection would draw 1.5 m away in each direction.
        const int sideIndex = static_cast<int>(side - sides.begin());
        for (int dx = -1; dx <= 1; ++dx)
            for (int dz = -1; dz <= 1; ++dz)
                for (const auto& [id, weight] :
                     _selector->blendAt(sideIndex, eye + kNeighbourMetres * glm::dvec2(dx, dz)).textures)
                    r.soon.push_back(id);
    }
    for (const walls::WallBlend& b : _seen.beyond)
        for (const auto& [id, weight] : b.textures) r.now.push_back(id);
    // Then what the eye will draw further along its way, nearest first, in view or not.
    for (const walls::FrameSelection& s : aheadSelections)
        for (const std::vector<walls::WallBlend>* walls : {&s.walls, &s.beyond})
            for (const walls::WallBlend& b : *walls)
                for (const auto& [id, weight] : b.textures) r.soon.push_back(id);
    if (!_drawTextures) r.now.clear(), r.soon.clear();
    if (!_requestCells) return r;
    r.cellsNow = _selection.allGeometry() ? std::vector<int>{} : _selection.geometryCells;
    auto soon = [&](int cell) {
        if (std::find(r.cellsSoon.begin(), r.cellsSoon.end(), cell) == r.cellsSoon.end()) r.cellsSoon.push_back(cell);
    };
    // The cells the selection draws 1.5 m away in each direction (as the textures' neighbouring
    // zones), then those behind every wall it selects, in view or not (a turn shows them).
    for (int dx = -1; dx <= 1; ++dx)
        for (int dz = -1; dz <= 1; ++dz)
            if (dx != 0 || dz != 0)
                for (int c : _selector->select(_eye + kNeighbourMetres * glm::dvec3(dx, 0, dz)).geometryCells) soon(c);
    for (const std::vector<walls::WallBlend>* walls : {&_selection.walls, &_selection.beyond})
        for (const walls::WallBlend& b : *walls) soon(_walls->plan.walls[b.wall].cells[1 - b.side]);
    for (const walls::FrameSelection& s : aheadSelections)
        for (int c : s.geometryCells) soon(c);
    return r;
}

FramePlan FramePlanner::plan(const Residency& resident, const Residency& cellResident) {
    assert(!_planned && "plan() follows requests(), once per frame");
    _planned = true;
    _cellResident = cellResident;
    FramePlan p;
    p.eyeWorld = _eye;
    if (!_selector) {
        p.cell = scenes::findCell(_description.cells, _eye);  // reported only
        p.geometryCells.assign(_description.cells.size(), true);
        p.objects = objectsOfCells(_scene, p.geometryCells);
        return p;
    }
    p.cell = _selection.cell;
    for (const walls::WallBlend& b : _selection.walls)
        if (b.zone >= 0) {
            p.zone = b.zone;
            break;
        }
    p.geometryCells.assign(_description.cells.size(), _selection.allGeometry());
    for (int c : _selection.geometryCells) setCell(p.geometryCells, c, true);
    _cellNeeded.assign(_description.cells.size(), false);
    setCell(_cellNeeded, p.cell, true);
    p.walls = _outOfView;
    const bool warp = _transition == Transition::Warp;
    // The control: the selection's geometry weights, no texture.
    auto bare = [&](const walls::WallBlend& b, bool beyond) {
        if (b.geometryWeight > 0.0) setCell(_cellNeeded, _walls->plan.walls[b.wall].cells[1 - b.side], true);
        p.walls.push_back(WallState{b.wall, {}, b.geometryWeight, false, beyond});
    };
    for (const walls::WallBlend& selected : _seen.walls) {
        if (!_drawTextures) {
            bare(selected, false);
            continue;
        }
        const walls::WallBlend b = warp ? binaryBlend(selected) : selected;
        WallState state = chooseWall(b, resident, p);
        if (warp) applyWarp(b, warpWall(b, state), state, p);
        if (!state.textures.empty()) addDraw(b, state, p);
        p.walls.push_back(std::move(state));
    }
    // Beyond a neighbour drawn as geometry: its far walls, faded like any other (no warp).
    for (const walls::WallBlend& selected : _seen.beyond) {
        if (!_drawTextures) {
            bare(selected, true);
            continue;
        }
        const walls::WallBlend b = warp ? binaryBlend(selected) : selected;
        WallState state = chooseWall(b, resident, p);
        if (!state.textures.empty()) addDraw(b, state, p);
        state.beyond = true;
        p.walls.push_back(std::move(state));
    }
    // Geometry paging: a cell that only walls kept as textures wanted is not drawn.
    if (_cellResident)
        for (std::size_t c = 0; c < p.geometryCells.size(); ++c) {
            if (p.geometryCells[c] && !_cellNeeded[c] && !_cellResident(static_cast<int>(c)))
                p.geometryCells[c] = false;
            if (p.geometryCells[c] && !_cellResident(static_cast<int>(c)))
                p.geometryForced.push_back(static_cast<int>(c));
        }
    // A morphing wall's cell behind is drawn by the warp pass only.
    for (const walls::WarpWall& w : p.warpWalls) setCell(p.geometryCells, w.cell, false);
    p.objects = objectsOfCells(_scene, p.geometryCells);
    if (_portalCulling) _portals->frameSets(p.cell, p.geometryCells, _scene, p.portals);
    measureError(p);
    return p;
}

// Step 3 of the header; a wall drawn as geometry adds its cell behind to the geometry cells.
WallState FramePlanner::chooseWall(const walls::WallBlend& b, const Residency& resident, FramePlan& p) {
    const walls::PlannedWall& planned = _walls->plan.walls[b.wall];
    WallState state{b.wall, b.textures, b.geometryWeight, false};
    auto allResident = [&](const TextureSet& set) {
        return !set.empty() && std::all_of(set.begin(), set.end(), [&](auto& t) { return resident(t.first); });
    };
    Memory& m = _memory[b.wall];
    if (!b.textures.empty() && !allResident(b.textures)) {
        state.fallback = true;
        const bool keep = m.lastSide == b.side && allResident(m.lastTextures) && withinBound(m.lastTextures, planned);
        state.textures = keep ? m.lastTextures : TextureSet{};
        if (state.textures.empty()) state.geometryWeight = 1.0;
    }
    const int behind = planned.cells[1 - b.side];
    if (state.geometryWeight > 0.0 && _cellResident && !_cellResident(behind)) keepTexturesFor(b, resident, state, p);
    if (state.fallback && state.textures.empty()) ++p.geometryFallbacks;
    if (state.geometryWeight > 0.0) {
        setCell(p.geometryCells, behind, true);
        setCell(_cellNeeded, behind, true);
    }
    if (!state.textures.empty()) {
        m.lastSide = b.side;
        m.lastTextures = state.textures;
    }
    return state;
}

// Geometry paging (header, step 4): the wall's cell behind is not resident, so it draws
// textures alone when any within alpha are resident: this frame's without the geometry weight,
// else the last ones drawn from this side.
void FramePlanner::keepTexturesFor(const walls::WallBlend& b, const Residency& resident, WallState& state,
                                   FramePlan& p) {
    auto allResident = [&](const TextureSet& set) {
        return !set.empty() && std::all_of(set.begin(), set.end(), [&](auto& t) { return resident(t.first); });
    };
    TextureSet kept;
    if (allResident(state.textures)) {
        kept = state.textures;
    } else {
        const Memory& m = _memory[b.wall];
        if (m.lastSide == b.side && allResident(m.lastTextures) &&
            withinBound(m.lastTextures, _walls->plan.walls[b.wall]))
            kept = m.lastTextures;
    }
    double total = 0.0;
    for (const auto& [id, weight] : kept) total += weight;
    if (total <= 0.0) return;  // nothing proven to show: the geometry is drawn (geometryForced)
    for (auto& [id, weight] : kept) weight /= total;
    state.textures = std::move(kept);
    state.geometryWeight = 0.0;
    state.fallback = true;
    ++p.geometryMisses;
}

// The quad of a wall drawing textures: the largest weights first, at most kMaxWallTextures.
void FramePlanner::addDraw(const walls::WallBlend& b, const WallState& state, FramePlan& p) const {
    // Textures seen from the back were baked on the mirrored quad (walls/gl/baker.h).
    WallDrawPlan d{b.wall, walls::quadSeenFrom(_walls->plan.walls[b.wall].quad, b.side), {}};
    TextureSet set = state.textures;
    std::sort(set.begin(), set.end(), [](auto& a, auto& c) { return a.second > c.second; });
    double total = 0.0, kept = 0.0;
    for (const auto& [id, weight] : set) {
        total += weight;
        if (static_cast<int>(d.textures.size()) == walls::kMaxWallTextures) continue;
        kept += weight;
        d.textures.emplace_back(id, weight);
    }
    // More than kMaxWallTextures (never planned): the kept ones take the dropped weight.
    if (kept > 0.0 && kept != total)
        for (auto& t : d.textures) t.second = t.second * total / kept;
    p.wallDraws.push_back(std::move(d));
}

// True when every texture of `set` is within the plan's alpha for the eye: a stale texture
// beyond the bound is worse than the geometry.
bool FramePlanner::withinBound(const TextureSet& set,
                               const walls::PlannedWall& /*wall: the texture ids carry it*/) const {
    const double alpha = glm::radians(_walls->plan.alphaDeg) + walls::kErrorTolerance;
    for (const auto& [id, weight] : set) {
        auto it = _textures.find(id);
        if (it == _textures.end() || walls::textureErrorAt(_walls->plan, *it->second, _eye) > alpha) return false;
    }
    return true;
}

// Transition::Warp after chooseWall (header): starts, continues or ends the wall's warp-morph
// and says what the warp does to the wall.
FramePlanner::WarpOutcome FramePlanner::warpWall(const walls::WallBlend& b, const WallState& state) {
    const walls::PlannedWall& planned = _walls->plan.walls[b.wall];
    std::optional<glm::dvec3> samplingPoint;
    if (!state.textures.empty()) {
        const auto largest = std::max_element(state.textures.begin(), state.textures.end(),
                                              [](auto& x, auto& y) { return x.second < y.second; });
        if (auto t = _textures.find(largest->first); t != _textures.end()) samplingPoint = t->second->samplingPoint;
    }
    Memory& m = _memory[b.wall];
    const Look look = state.textures.empty() ? Look::Geometry : Look::Texture;
    if (m.look != Look::Nothing && look != m.look &&
        (look == Look::Texture ? samplingPoint.has_value() : m.lastSamplingPoint.has_value())) {
        m.phase = look == Look::Geometry ? MorphPhase::ToGeometry : MorphPhase::ToTexture;
        m.start = _input.time;
        m.samplingPoint = look == Look::Geometry ? *m.lastSamplingPoint : *samplingPoint;
    }
    m.look = look;
    if (samplingPoint) m.lastSamplingPoint = samplingPoint;
    const double s = (_input.time - m.start) / _morphSeconds;
    if (m.phase != MorphPhase::Idle && !(s >= 0.0 && s < 1.0)) m.phase = MorphPhase::Idle;
    WarpOutcome out{
        WarpOutcome::Kind::None,
        walls::WarpWall{walls::quadSeenFrom(planned.quad, b.side), samplingPoint.value_or(glm::dvec3(0.0)), -1},
        m.phase, s};
    if (m.phase != MorphPhase::Idle) {
        // The viewpoint moves from the sampling point to the eye (to geometry) or back.
        out.warp.samplingPoint =
            m.phase == MorphPhase::ToGeometry ? glm::mix(m.samplingPoint, _eye, s) : glm::mix(_eye, m.samplingPoint, s);
        out.warp.cell = planned.cells[1 - b.side];
    } else if (!samplingPoint || state.geometryWeight > 0.0) {
        return out;
    }
    if (!warpConditioned(out.warp)) {
        m.phase = MorphPhase::Idle;
        out.kind = WarpOutcome::Kind::Fallback;
        return out;
    }
    out.kind = m.phase != MorphPhase::Idle ? WarpOutcome::Kind::Morph : WarpOutcome::Kind::Warp;
    return out;
}

void FramePlanner::applyWarp(const walls::WallBlend& b, const WarpOutcome& outcome, WallState& state, FramePlan& p) {
    using Kind = WarpOutcome::Kind;
    if (outcome.kind == Kind::None) return;
    if (outcome.kind == Kind::Warp || outcome.kind == Kind::Morph) p.warpWalls.push_back(outcome.warp);
    if (outcome.kind == Kind::Warp) return;
    state.textures.clear();
    state.geometryWeight = 1.0;
    if (outcome.kind == Kind::Morph) {
        p.morphs.push_back({b.wall, outcome.phase, outcome.share});
        return;
    }
    state.fallback = true;
    setCell(p.geometryCells, _walls->plan.walls[b.wall].cells[1 - b.side], true);
    ++p.warpFallbacks;
}

// True when the warp of `warp` is well-conditioned for every given view (display/warp.h).
bool FramePlanner::warpConditioned(const walls::WarpWall& warp) const {
    for (const display::ScreenView& view : _views)
        if (!(display::warpCondition(walls::warpFor(warp, view, _caveFromWorld, _display.depthRange().near)) <=
              display::kMaxWarpCondition))
            return false;
    return true;
}

// Conservative: false only when all four corners of the wall lie outside one clip plane of
// every given view (x, y within ±w, in front of the eye).
bool FramePlanner::wallInView(int wall) const {
    const display::ScreenQuad& q = _walls->plan.walls[wall].quad;
    const glm::dvec3 corners[4] = {q.lowerLeft, q.lowerRight, q.upperLeft, q.lowerRight + q.upperLeft - q.lowerLeft};
    for (const display::ScreenView& view : _views) {
        const glm::dmat4 clipFromWorld = view.frustum.clipFromFrame() * _caveFromWorld;
        int outside[5] = {0, 0, 0, 0, 0};
        for (const glm::dvec3& c : corners) {
            const glm::dvec4 p = clipFromWorld * glm::dvec4(c, 1.0);
            outside[0] += p.x < -p.w;
            outside[1] += p.x > p.w;
            outside[2] += p.y < -p.w;
            outside[3] += p.y > p.w;
            outside[4] += p.w <= 0.0;
        }
        if (std::none_of(std::begin(outside), std::end(outside), [](int n) { return n == 4; })) return true;
    }
    return false;
}

void FramePlanner::measureError(FramePlan& p) const {
    // The bounds are within kErrorTolerance of the true maximum (walls/angular_error.h).
    const double alpha = glm::radians(_walls->plan.alphaDeg) + walls::kErrorTolerance;
    double worst = 0.0;
    for (WallState& s : p.walls) {
        double wall = 0.0;
        for (const auto& [id, weight] : s.textures) {
            auto it = _textures.find(id);
            if (weight <= 0.0 || it == _textures.end()) continue;
            const double error = walls::textureErrorAt(_walls->plan, *it->second, _eye);
            wall = std::max(wall, error);
            s.texturesOverAlpha += error > alpha ? 1 : 0;
        }
        s.errorDeg = glm::degrees(wall);
        p.texturesOverAlpha += s.texturesOverAlpha;
        worst = std::max(worst, wall);
    }
    p.maxErrorDeg = glm::degrees(worst);
    if (worst <= 0.0) return;
    const std::vector<ViewScale> views = viewScales();
    for (const WallState& s : p.walls)
        if (s.errorDeg > 0.0)
            p.maxErrorPixels = std::max(p.maxErrorPixels, s.errorDeg * wallPixelsPerDegree(s.wall, views));
}

// One view of the frame as wallPixelsPerDegree needs it; the same for every wall.
struct FramePlanner::ViewScale {
    glm::dmat4 viewFromWorld{1.0};
    display::ViewScreen screen;
    double pixelsPerDegree = 0.0;  // display::minPixelsPerDegree(screen)
};

std::vector<FramePlanner::ViewScale> FramePlanner::viewScales() const {
    std::vector<ViewScale> out;
    out.reserve(_views.size());
    for (const display::ScreenView& view : _views) {
        ViewScale v;
        v.viewFromWorld = view.frustum.viewFromFrame * _caveFromWorld;
        v.screen = display::viewScreen(view.frustum, {view.pass.viewport.width, view.pass.viewport.height});
        v.pixelsPerDegree = display::minPixelsPerDegree(v.screen);
        out.push_back(v);
    }
    return out;
}

// A texture is drawn on its wall's quad (walls/texture_rect.h), so its error shows only on the
// screens where that quad appears: the most of their pixels per degree of visual angle.
double FramePlanner::wallPixelsPerDegree(int wall, const std::vector<ViewScale>& views) const {
    const display::ScreenQuad& q = _walls->plan.walls[wall].quad;
    const glm::dvec3 corners[4] = {q.lowerLeft, q.lowerRight, q.upperLeft, q.lowerRight + q.upperLeft - q.lowerLeft};
    double most = 0.0;
    for (const ViewScale& v : views) {
        std::array<glm::dvec3, 4> inView;
        for (int c = 0; c < 4; ++c) inView[c] = glm::dvec3(v.viewFromWorld * glm::dvec4(corners[c], 1.0));
        if (display::maxPixelsPerRadianInFront(v.screen, inView) > 0.0) most = std::max(most, v.pixelsPerDegree);
    }
    return most;
}

std::vector<int> objectsOfCells(const scenes::Scene& scene, const std::vector<bool>& cells) {
    std::vector<int> out;
    for (int i = 0; i < static_cast<int>(scene.objects.size()); ++i) {
        const scenes::Object& o = scene.objects[i];
        const int count = static_cast<int>(cells.size());
        if (o.role == scenes::Role::Structure || o.cell < 0 || o.cell >= count ||
            scenes::anyCellOf(o, [&](int c) { return c < count && cells[c]; }))
            out.push_back(i);
    }
    return out;
}

}  // namespace cavewall::walkthrough

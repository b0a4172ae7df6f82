#include "input/path_file.h"

#include "config/json_reader.h"
#include "input/pose_math.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace cavewall::input {
namespace {

const char* const kHeadColumns[] = {"t", "x", "y", "z", "qx", "qy", "qz", "qw"};
const char* const kHandColumns[] = {"hx", "hy", "hz", "hqx", "hqy", "hqz", "hqw"};

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

std::vector<std::string_view> splitCommas(std::string_view line) {
    std::vector<std::string_view> out;
    while (true) {
        const auto comma = line.find(',');
        out.push_back(trim(line.substr(0, comma)));
        if (comma == std::string_view::npos) return out;
        line.remove_prefix(comma + 1);
    }
}

glm::dquat normalisedQuat(glm::dquat q, const std::string& where) {
    const double n = glm::length(q);
    if (!(n > 1e-6)) throw Error(where + ": expected a unit quaternion, got one of length " + config::formatNumber(n));
    return q / n;
}

void checkTimes(const std::vector<PathKey>& keys, const std::string& where) {
    const std::size_t n = keys.size();
    if (n >= 2 && !(keys[n - 1].time > keys[n - 2].time))
        throw Error(where + ": times must strictly increase (expected more than " +
                    config::formatNumber(keys[n - 2].time) + ", got " + config::formatNumber(keys[n - 1].time) + ")");
}

Pose csvPose(const std::vector<double>& v, std::size_t first, const std::string& where) {
    Pose p;
    p.position = {v[first], v[first + 1], v[first + 2]};
    p.orientation = normalisedQuat(glm::dquat(v[first + 6], v[first + 3], v[first + 4], v[first + 5]), where);
    return p;
}

std::size_t parseCsvHeader(std::string_view line, const std::string& where) {
    const auto cols = splitCommas(line);
    const bool withHand = cols.size() == 15;
    bool ok = cols.size() == 8 || withHand;
    for (std::size_t i = 0; ok && i < cols.size(); ++i) ok = cols[i] == (i < 8 ? kHeadColumns[i] : kHandColumns[i - 8]);
    if (!ok)
        throw Error(where +
                    ": expected the header t,x,y,z,qx,qy,qz,qw (optionally followed by "
                    "hx,hy,hz,hqx,hqy,hqz,hqw), got '" +
                    std::string(line) + "'");
    return cols.size();
}

}  // namespace

RecordedPath parsePathCsv(std::string_view text, const std::string& source) {
    RecordedPath path;
    std::size_t columns = 0, lineNo = 0;
    while (!text.empty()) {
        const auto nl = text.find('\n');
        const std::string_view line = trim(text.substr(0, nl));
        text = nl == std::string_view::npos ? std::string_view{} : text.substr(nl + 1);
        ++lineNo;
        if (line.empty() || line.front() == '#') continue;
        const std::string where = source + ":" + std::to_string(lineNo);
        if (columns == 0) {
            columns = parseCsvHeader(line, where);
            continue;
        }
        const auto cells = splitCommas(line);
        if (cells.size() != columns)
            throw Error(where + ": expected " + std::to_string(columns) + " values, got " +
                        std::to_string(cells.size()));
        std::vector<double> v(columns);
        for (std::size_t i = 0; i < columns; ++i) {
            auto [end, ec] = std::from_chars(cells[i].data(), cells[i].data() + cells[i].size(), v[i]);
            if (ec != std::errc() || end != cells[i].data() + cells[i].size() || !std::isfinite(v[i]))
                throw Error(where + ": column " + (i < 8 ? kHeadColumns[i] : kHandColumns[i - 8]) +
                            ": expected a finite number, got '" + std::string(cells[i]) + "'");
        }
        path.head.push_back({v[0], csvPose(v, 1, where)});
        if (columns == 15) path.hand.push_back({v[0], csvPose(v, 8, where)});
        checkTimes(path.head, where);
    }
    if (columns == 0) throw Error(source + ": expected a header line t,x,y,z,qx,qy,qz,qw, got an empty file");
    if (path.head.size() < 2)
        throw Error(source + ": expected at least 2 samples, got " + std::to_string(path.head.size()));
    return path;
}

RecordedPath parsePathJson(std::string_view text, const std::string& source) {
    const auto doc = config::JsonDocument::fromText(text, source);
    const config::JsonNode root = doc.root();
    root.expectObject();
    root.expectKeys({"samples"});
    const auto samples = root.at("samples").items(2);
    RecordedPath path;
    const bool withHand = samples.front().has("hand");
    for (const auto& s : samples) {
        s.expectObject();
        s.expectKeys({"t", "position", "orientation", "hand"});
        const double t = s.at("t").number();
        path.head.push_back({t, {s.at("position").vec3(), s.at("orientation").rotation()}});
        checkTimes(path.head, s.at("t").where());
        if (s.has("hand") != withHand)
            s.fail(withHand ? "missing required key 'hand' (the first sample has one)"
                            : "unexpected key 'hand' (the first sample has none)");
        if (!withHand) continue;
        const auto h = s.at("hand");
        h.expectObject();
        h.expectKeys({"position", "orientation"});
        path.hand.push_back({t, {h.at("position").vec3(), h.at("orientation").rotation()}});
    }
    return path;
}

RecordedPath loadRecordedPath(const std::filesystem::path& file) {
    const std::string ext = file.extension().string();
    if (ext != ".csv" && ext != ".json")
        throw Error(file.string() + ": expected a .csv or .json path file, got extension '" + ext + "'");
    const std::string text = config::readTextFile(file);
    return ext == ".csv" ? parsePathCsv(text, file.string()) : parsePathJson(text, file.string());
}

Pose interpolatePath(const std::vector<PathKey>& keys, double time) {
    if (time <= keys.front().time) return keys.front().pose;
    if (time >= keys.back().time) return keys.back().pose;
    const auto it =
        std::upper_bound(keys.begin(), keys.end(), time, [](double t, const PathKey& k) { return t < k.time; });
    const std::size_t i = static_cast<std::size_t>(it - keys.begin()) - 1, n = keys.size();
    const auto tangent = [&](std::size_t k) {
        const std::size_t a = k == 0 ? 0 : k - 1, b = k + 1 == n ? k : k + 1;
        return (keys[b].pose.position - keys[a].pose.position) / (keys[b].time - keys[a].time);
    };
    const PathKey &k0 = keys[i], &k1 = keys[i + 1];
    const double h = k1.time - k0.time, u = (time - k0.time) / h, u2 = u * u, u3 = u2 * u;
    Pose p;
    p.position = (2 * u3 - 3 * u2 + 1) * k0.pose.position + (u3 - 2 * u2 + u) * h * tangent(i) +
                 (-2 * u3 + 3 * u2) * k1.pose.position + (u3 - u2) * h * tangent(i + 1);
    p.orientation = slerpShortest(k0.pose.orientation, k1.pose.orientation, u);
    return p;
}

namespace {

class PathFileSource : public TrackerSource {
public:
    PathFileSource(RecordedPath path, bool loop, std::string text)
        : _path(std::move(path)), _loop(loop), _text(std::move(text)) {}

    Sample poll(double now) override {
        if (!_started) {
            _started = true;
            _startTime = now;
        }
        const double first = _path.head.front().time, duration = _path.head.back().time - first;
        double t = now - _startTime;
        if (_loop) t = std::fmod(std::max(t, 0.0), duration);
        Sample s;
        s.time = now;
        s.head = interpolatePath(_path.head, first + t);
        s.headValid = true;
        s.handValid = !_path.hand.empty();
        if (s.handValid) s.hand = interpolatePath(_path.hand, first + t);
        return s;
    }
    std::string describe() const override { return "recorded path (" + _text + ")"; }

private:
    RecordedPath _path;
    bool _loop;
    std::string _text;
    bool _started = false;
    double _startTime = 0.0;
};

}  // namespace

std::unique_ptr<TrackerSource> makePathFileSource(const TrackerSpec& spec) {
    spec.expectParams({"loop"});
    if (spec.target().empty()) spec.fail("expected file:PATH, got an empty path");
    const bool loop = spec.flag("loop", false);
    return std::make_unique<PathFileSource>(loadRecordedPath(spec.target()), loop, spec.text());
}

}  // namespace cavewall::input

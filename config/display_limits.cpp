#include "config/display_limits.h"

#include <cctype>

namespace cavewall::config {

std::string fileNameProblem(std::string_view name) {
    auto quoted = [&] {
        std::string q;
        for (char c : name.substr(0, 80))
            q += (c >= 32 && c < 127)
                     ? std::string(1, c)
                     : "\\x" + std::string(1, "0123456789abcdef"[(c >> 4) & 15]) + "0123456789abcdef"[c & 15];
        return "'" + q + (name.size() > 80 ? "...'" : "'");
    };
    if (name.empty() || name.size() > 64)
        return "expected a name of 1 to 64 characters (it names an output file), got " + std::to_string(name.size());
    for (char c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.')
            return "expected only letters, digits, '_', '-' and '.' (it names an output file), got " + quoted();
    if (name[0] == '.' || name[0] == '-')
        return "expected a name that does not start with '.' or '-' (it names an output file), got " + quoted();
    std::string lower(name);
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (lower == "foldout" || lower == "bench")
        return "the name " + quoted() + " is reserved for the program's own output files (expected another name)";
    return "";
}

TrackingVolume trackingVolumeOf(const DisplayConfig& config) {
    if (config.tracking.volume) return TrackingVolume{(*config.tracking.volume)[0], (*config.tracking.volume)[1]};
    TrackingVolume v{config.viewer.headPosition, config.viewer.headPosition};
    for (const Screen& s : config.screens)
        for (const glm::dvec3& p : {s.lowerLeft, s.lowerRight, s.upperLeft, s.lowerRight + s.upperLeft - s.lowerLeft}) {
            v.min = glm::min(v.min, p);
            v.max = glm::max(v.max, p);
        }
    v.min -= glm::dvec3(kTrackingMargin);
    v.max += glm::dvec3(kTrackingMargin);
    return v;
}

}  // namespace cavewall::config

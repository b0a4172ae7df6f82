#pragma once
// Calibration from tracked points: the transform caveFromTracker that best maps points measured
// in the tracker frame onto the same points known in the cave frame (a wand tip held at marked
// screen corners), in the least-squares sense.
//
// Method: Horn's closed-form absolute orientation with unit quaternions (Horn 1987). With both
// point sets centred on their centroids, the rotation is the unit quaternion that maximises
// sum(cave_i . R tracker_i): the eigenvector of the largest eigenvalue of a symmetric 4x4 matrix
// built from the cross-covariance (found here by cyclic Jacobi rotations, in double). The
// translation maps the tracker centroid onto the cave centroid. With a scale, the scale is
// lambda_max / sum|tracker_i|^2, the least-squares scale for residuals measured in the cave
// frame. The result is always a proper rotation (never a reflection); points that fit a mirror
// image better are refused.
//
// Units: metres in and out; residuals in metres; angles in radians (yawPitchRollOf).

#include "config/error.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace cavewall::input {

struct PointPair {
    glm::dvec3 tracker{0.0};  // measured, tracker frame (metres, after the adapter's units)
    glm::dvec3 cave{0.0};     // known, cave frame (metres)
    bool operator==(const PointPair&) const = default;
};

// A screen's corners as measured by the tracker (tracker frame, metres), to be placed in the
// cave frame by the fitted calibration (fitScreenCorners).
struct TrackedScreen {
    std::string name;  // the screen of the display configuration
    glm::dvec3 lowerLeft{0.0}, lowerRight{0.0}, upperLeft{0.0};
    bool operator==(const TrackedScreen&) const = default;
};

// A pairs file, JSON, metres in both frames; "label" is optional and only printed; "screens" is
// optional and gives screens' corners measured in the tracker frame:
//   {"pairs": [{"tracker": [0.12, 0.03, 1.51], "cave": [-1.5, 0, -1.5], "label": "front lowerLeft"},
//              ...],
//    "screens": {"front": {"lowerLeft": [x, y, z], "lowerRight": [x, y, z], "upperLeft": [x, y, z]}}}
struct PairsFile {
    std::vector<PointPair> pairs;
    std::vector<std::string> labels;     // one per pair; empty when not given
    std::vector<TrackedScreen> screens;  // by name
};
// Parses a pairs file's text (types, finiteness, unknown keys, every coordinate within
// config::kMaxCoordinate (1000 m) on each axis; at most 10000 pairs). `source`
// names the file in messages. Throws Error. The geometric rules are fitCaveFromTracker's.
PairsFile parsePairsFile(std::string_view jsonText, const std::string& source);

struct CalibrationOptions {
    bool fitScale = false;       // fit a uniform scale too (a similarity instead of a rigid map)
    double minScale = 0.5;       // with fitScale: a fitted scale outside [min, max] is refused
    double maxScale = 2.0;       //   (tracker units mistaken, pairs swapped)
    double minSpread = 0.01;     // metres: the least distance between two points and the least
                                 // spread across their line (below: duplicate or collinear)
    double noise = 0.002;        // metres: the expected measurement noise of one point
    double outlierFactor = 5.0;  // warn about a residual above outlierFactor * noise
    double maxRmsFactor = 50.0;  // refuse a fit whose RMS residual is above maxRmsFactor * noise
    bool operator==(const CalibrationOptions&) const = default;
};

struct CalibrationFit {
    glm::dmat4 caveFromTracker{1.0};    // scale * rotation in the upper 3x3, translation in column 3
    glm::dmat3 rotation{1.0};           // the rotation alone
    double scale = 1.0;                 // 1 unless fitScale
    std::vector<double> residuals;      // per pair, metres: |caveFromTracker * tracker - cave|
    double rms = 0.0;                   // metres
    double max = 0.0;                   // metres
    std::vector<std::string> warnings;  // residuals far above the noise, one line each
};

// The fit of `pairs` (at least 3, finite, distinct, not collinear in either frame). `source`
// names the input in messages. Throws Error naming the problem and the measured figure:
// "pairs.json: the cave points are collinear: their spread across their common line is 0.3 mm,
// expected at least 10.0 mm" (the spread: the largest distance of a point from the line).
// Refuses fewer than 3 pairs, non-finite values, two points closer than minSpread, collinear
// points, points that fit a mirror image better than a rotation, and (with fitScale) a scale
// outside [minScale, maxScale], and a fit whose RMS residual is above maxRmsFactor * noise (100 mm
// at the defaults: tracker units mistaken without fitScale, pairs shuffled). Residuals above
// outlierFactor * noise come back as warnings.
CalibrationFit fitCaveFromTracker(const std::vector<PointPair>& pairs, const CalibrationOptions& options,
                                  const std::string& source);

// An axis-aligned box of the cave frame (metres): the volume a calibration is judged over.
struct Box {
    glm::dvec3 min{0.0}, max{0.0};
    bool operator==(const Box&) const = default;
};

// How far a calibration maps points from where they belong, over a box: `rms` is the root mean
// square over the box's volume (uniform density), `worstCorner` the largest over the box (an
// affine error is largest at a corner). Metres.
struct VolumeError {
    double rms = 0.0;
    double worstCorner = 0.0;
};

// How far `fitted` maps points from where `truth` maps them, over `box` of the cave frame: for
// each cave point c in the box, the distance between fitted * truth^-1 * c and c (where the two
// calibrations map the tracker point that truth puts at c). Exact: the difference of two affine
// maps is affine, so its mean square over a box has a closed form and its largest value is at a
// corner.
VolumeError calibrationDifference(const glm::dmat4& fitted, const glm::dmat4& truth, const Box& box);

// The error to expect over `box` from the rigid fit of points at `cave` (cave frame, metres)
// whose tracker measurements carry Gaussian noise of `sigma` metres on every coordinate: the
// first-order (small-noise) covariance of Horn's fit, Var(translation at the centroid) = sigma^2
// / n per axis and Var(rotation) = sigma^2 S^-1 with S = sum(|a_i|^2 I - a_i a_i^T) over the
// centred points, so E|e(p)|^2 = sigma^2 (3 / n + r^T (tr(S^-1) I - S^-1) r) at r = p - centroid.
// `rms` is the root of that mean over the box, `worstCorner` its root at the worst corner (both
// expectations over the noise, not one fit's error). Needs 3 or more non-collinear points.
VolumeError predictedRigidError(const std::vector<glm::dvec3>& cave, double sigma, const Box& box);

// The noise per coordinate that a fit's residuals imply: sqrt(sum r_i^2 / (3 n - k)), with k = 6
// fitted parameters for a rigid fit and 7 with a scale (0 when 3 n <= k).
double noiseFromResiduals(const CalibrationFit& fit, bool fitScale);

// The expected error over `box` per metre of noise per coordinate (predictedRigidError's rms for
// sigma = 1) above which the points are poorly spread: the eight corners of a cube give 0.71 over
// the cube, the four corners of one of its walls 1.29, the corners of a cube a third its size
// at its centre 1.22.
inline constexpr double kPoorSpreadFactor = 1.0;

// A line of advice when `cave` points (at least 3, not collinear) fix the calibration poorly
// over `box` (the volume the display's screens enclose; the message says so): their expected
// error there over kPoorSpreadFactor times the noise. Empty otherwise.
std::string spreadAdvice(const std::vector<glm::dvec3>& cave, const Box& box, const std::string& source);

// The rotation R that maximises sum(b_i . R a_i) for centred point sets a and b of one size
// (Horn 1987, without the checks above): the unit quaternion that is the eigenvector of the
// largest eigenvalue of Horn's matrix N, and that eigenvalue, which equals sum(b_i . R a_i).
struct HornRotation {
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
    double lambdaMax = 0.0;
};
HornRotation hornRotation(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b);

// A screen's corners in the cave frame from its corners measured in the tracker frame: mapped
// by caveFromTracker, then squared into a rectangle (measured corners never meet at exactly
// 90°, and the display configuration requires 90° within 0.1°). lowerLeft and the two edge
// lengths are kept; both edges turn by half the error, in their plane, towards 90°.
struct ScreenCorners {
    glm::dvec3 lowerLeft{0.0}, lowerRight{0.0}, upperLeft{0.0};  // cave frame, metres
    double squaredByDeg = 0.0;                                   // the measured angle at lowerLeft minus 90°
};
ScreenCorners fitScreenCorners(const glm::dmat4& caveFromTracker, const TrackedScreen& tracked);

// The angles (radians) of input::yawPitchRoll that give rotation `r`: {yaw about +Y, pitch about
// the turned +X, roll about the turned +Z}; pitch in [-pi/2, pi/2]. At pitch +-pi/2, roll is 0.
glm::dvec3 yawPitchRollOf(const glm::dmat3& r);

// Eigenvalues and eigenvectors of a symmetric 4x4 matrix by cyclic Jacobi rotations: values[i]
// belongs to column i of `vectors` (unit length). Exposed for tests.
struct SymmetricEigen4 {
    glm::dvec4 values{0.0};
    glm::dmat4 vectors{1.0};
};
SymmetricEigen4 symmetricEigen(const glm::dmat4& m);

}  // namespace cavewall::input

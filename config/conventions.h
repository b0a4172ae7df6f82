#pragma once
// Units, frames and naming conventions used everywhere in cavewall. Read this once.
//
// Units: metres, seconds, radians in code (degrees only in files and on the command line, and
// named ...Deg there). Right-handed coordinates, +Y up.
//
// Frames:
//  - tracker: whatever the tracking system reports, converted to metres by its adapter.
//  - cave:    origin on the floor centre of the CAVE, +Y up, -Z towards the front wall
//             (a viewer standing at the origin looking at the front wall looks down -Z).
//             Screens, head and hand poses are given in this frame.
//  - world:   the scene's frame. Navigation moves the whole CAVE through the world
//             (worldFromCave); the eye in the world is worldFromCave * eyeInCave.
//  - view:    an eye's frame for one screen: origin at the eye, axes along the screen's right,
//             up and normal (towards the viewer), so the eye looks down -Z as in OpenGL.
//  - clip/NDC: OpenGL conventions for x and y (y up, [-1, 1]); depth is reversed-Z in [0, 1]
//             (1 at the near plane, 0 at the far plane or at infinity), meant for
//             glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE) with a 32-bit float depth buffer and
//             glDepthFunc(GL_GREATER).
//
// Transforms are named destinationFromSource (caveFromTracker, worldFromCave, viewFromWorld,
// clipFromView), so products read right to left: clipFromWorld = clipFromView * viewFromWorld.
// Matrices are GLM, column-major, applied to column vectors.
//
// Screen and wall quads are given by three corners, lowerLeft, lowerRight, upperLeft, as seen
// by a viewer in front of them; the fourth corner is lowerRight + upperLeft - lowerLeft. The
// front side is the one the normal cross(lowerRight - lowerLeft, upperLeft - lowerLeft)
// points to.
//
// Precision: geometry and transforms are double on the CPU. The GPU receives float matrices
// that are relative to the eye (see display/off_axis.h), so large world offsets render without
// jitter.

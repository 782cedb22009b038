#pragma once
/// A body's measurements, as a tailor takes them for made-to-measure patterns (Durupinar section 2: the panels'
/// corners are set from the body's girths and lengths), found from the closed mesh alone: horizontal cross-sections
/// at landmark heights, a girth being the tape measure around a section (the perimeter of its convex hull: a tape
/// spans the hollows). Works on any body in the BodyFrame convention (metres, +Y up, soles at y = 0, facing +Z).
#include <string>
#include <vector>

#include "clothbench/sim/body_frame.hpp"

namespace clothbench {

/// One closed loop of a horizontal cross-section: its points (x, z) [m] in order.
struct SectionLoop {
  std::vector<Eigen::Vector2d> points;
  double area() const;               ///< enclosed area [m^2] (unsigned)
  double girth() const;              ///< perimeter of the convex hull: a tape measure around it [m]
  Eigen::Vector2d centroid() const;  ///< mean of the points (x, z) [m]
  double width() const;              ///< extent along x [m]
  double reach(int side) const;      ///< the largest z (side > 0: the front) or the smallest (side < 0: the back) [m]
};

/// The cross-section of a closed triangle mesh by the plane y = height: its closed loops, largest area first.
/// A vertex exactly on the plane counts as below it, so every point of a loop lies inside an edge.
std::vector<SectionLoop> cross_section(const BodyFrame& body, double height);

/// One measurement: its name, the height it was taken at, its value, and how it was found.
struct Measurement {
  std::string name;     ///< "bust girth", "waist height", ...
  double value_m = 0;   ///< the girth or length [m]
  double height_m = 0;  ///< the height of the section it was taken on (or the landmark's own height) [m]
  std::string how;      ///< one line: the search that found it
};

/// The standing body's measurements (stature; neck, bust, under-bust, waist, hip, thigh, knee and upper-arm girths;
/// the heights of those landmarks and of the crotch and armpit; shoulder width; back length, inseam, waist to knee;
/// the chest girth at the armpits and the height of the shoulders' top where a shoulder seam ends).
/// The body stands upright with its arms away from its sides below the armpit (the rest poses here: A- or T-pose).
/// Throws std::invalid_argument naming what is missing when a landmark cannot be found (an open mesh, a body whose
/// legs do not part, arms held against the torso).
struct BodyMeasurements {
  std::vector<Measurement> all;  ///< in the order above
  /// The measurement of that name; throws std::out_of_range naming it when there is none.
  const Measurement& operator[](const std::string& name) const;
};
BodyMeasurements measure_body(const BodyFrame& body);

}  // namespace clothbench

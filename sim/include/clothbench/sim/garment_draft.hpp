#pragma once
/// Garments drafted from a body's measurements (Durupinar section 2: each panel's corners set from the body's
/// girths and lengths), so that any body gets a garment that fits it: the pattern a tailor would cut, written as
/// a `.pattern` file by `clothbench measure --draft`.
#include <string>
#include <vector>

#include "clothbench/sim/body_measure.hpp"
#include "clothbench/sim/garment.hpp"

namespace clothbench {

/// The ease of a size [cm]: what the garment adds to the hip girth. S 4, M 8, L 12, XL 16. Throws
/// std::invalid_argument naming the sizes for any other name.
double size_ease_cm(const std::string& size);
/// The sizes size_ease_cm knows, smallest first.
std::vector<std::string> draft_sizes();

/// The garment types draft_garment makes.
std::vector<std::string> draft_types();

/// A pattern of `type` for `body` (its measurements `m`, from measure_body) with `ease_cm` at the hip.
/// `skirt`: a front and a back panel from the waist to just above the knee, the hip girth plus the ease at the hip's
/// height, the waist girth plus 2 cm round the top (a waistband that fits, whatever the size), a little A-line below
/// the hip (room for a stride); sewn at the sides. The waistband is not attached (Durupinar 3.2 attaches it): it
/// holds on the waist as a fitted skirt's does, narrower than the hip below it. The panels are wrapped round the hip
/// section's centre, wide enough to clear it. Throws std::invalid_argument naming the types for an unknown one, and
/// for an ease below 0 or over 100 cm.
Pattern draft_garment(const std::string& type, const BodyFrame& body, const BodyMeasurements& m, double ease_cm);

}  // namespace clothbench

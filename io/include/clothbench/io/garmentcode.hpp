#pragma once
/// Import of GarmentCode pattern specifications (JSON, MIT; Korosteleva et al., pygarment):
/// panels with straight, quadratic, cubic and circle-arc edges, their 3D placement and stitches,
/// converted into sim's Pattern.
#include <string>
#include <string_view>

#include "clothbench/sim/body_frame.hpp"
#include "clothbench/sim/garment.hpp"

namespace clothbench {

/// Converts a GarmentCode specification into a Pattern. `file` names the input in errors.
/// - Outlines: `vertices` scaled to cm by `properties.units_in_meter`; edges must form one loop;
///   curvature control points relative to their edge (pygarment `rel_to_abs_2d`) or absolute;
///   curves are flattened into chords of at most 1 cm.
/// - Placement: pygarment places a panel point (u, v) at R (u, v, 0) + translation, R from
///   intrinsic XYZ Euler degrees. R becomes yaw/roll/pitch (any rotation fits); the translation
///   height becomes a fraction of `reference_body`'s box [m] (the body GarmentCode placed it for),
///   so the garment follows a taller or shorter body; x and z stay as cm offsets from the box centre.
/// - Stitches: each becomes a Seam; its orientation is the one that brings the two edges'
///   end points closest together in GarmentCode's 3D placement (the files carry no flag for it).
/// Throws InputError(located(file, line, message)) on malformed JSON or specifications.
Pattern parse_garmentcode(std::string_view json_text, const std::string& file, const Box3& reference_body);

/// Reads a GarmentCode `.json` file; the reference body is `mean_female.obj` beside it, else the
/// one in the data root (`garments/garmentcode/mean_female.obj`). Throws InputError.
Pattern load_garmentcode(const std::string& path);

/// Bounding box [m] of the vertices (`v` lines) of an OBJ file; throws InputError.
Box3 obj_bounding_box(const std::string& path);

}  // namespace clothbench

#pragma once
/// The papers' published figures, typed in from ../shared/papers and labelled with their source.
/// These are the only numbers in clothbench that do not come from a run.

namespace clothbench::paper {

/// Dressing paper (Vassilev et al. 2001, "Dressing virtual people"), Table 1 (SGI R12000).
struct DressingT1Row {
  const char* product;
  const char* method;  // "IS" or "OS"
  int vertices;
  int iterations;
  double total_s;
  double ms_per_iteration;
};
inline constexpr DressingT1Row kDressingT1[] = {
    {"shirt", "IS", 1800, 82, 1.3, 15.8},
    {"shirt", "OS", 1800, 149, 4.6, 30.8},
    {"dress", "IS", 3840, 130, 4.3, 33.0},
    {"dress", "OS", 3840, 150, 7.8, 52.0},
};

/// Dressing paper Table 2: minimum vertices with face-body collisions (IS method).
struct DressingT2Row {
  const char* product;
  int vertices;
  int iterations;
  double total_s;
  double ms_per_iteration;
};
inline constexpr DressingT2Row kDressingT2[] = {
    {"skirt", 336, 66, 0.206, 3.1},
    {"trousers", 560, 69, 0.334, 4.8},
    {"shirt", 544, 55, 0.268, 4.8},
    {"dress", 1024, 88, 0.784, 8.9},
};

/// Walking paper (Vassilev et al. 2001, "Fast cloth animation on walking avatars"), Table 1.
struct WalkingT1Row {
  const char* product;
  const char* method;
  int vertices;
  double ms_per_iteration, cdr_ms, cs_ms, cdr_pct, cs_pct;
};
inline constexpr WalkingT1Row kWalkingT1[] = {
    {"shirt", "IS", 1800, 15.8, 7.6, 8.2, 48.1, 51.9},
    {"shirt", "OS", 1800, 30.8, 22.5, 8.3, 73.0, 27.0},
    {"dress", "IS", 3840, 33.0, 15.1, 17.9, 45.7, 54.3},
    {"dress", "OS", 3840, 52.0, 34.2, 17.8, 65.7, 34.3},
};

/// Walking paper Table 2 (PC, Pentium III 1 GHz, GeForce2): animation speed.
struct WalkingT2Row {
  const char* product;
  int vertices;
  double s_per_frame, fps;
};
inline constexpr WalkingT2Row kWalkingT2[] = {
    {"skirt", 672, 0.244, 4.1},
    {"dress with sleeves", 2300, 0.294, 3.4},
};

/// Durupinar & Gudukbay 2007, Fig. 6 caption: total sewing time (Pentium IV 3 GHz, dt 0.05 s).
struct DurupinarF6Row {
  const char* product;
  int vertices;
  int seams;
  double total_sewing_s;
};
inline constexpr DurupinarF6Row kDurupinarF6[] = {
    {"skirt", 1400, 61, 4.313},
    {"trousers", 2774, 140, 6.863},
};

/// Durupinar & Gudukbay 2007, section 5: frame rates of an animation sequence (Pentium IV 3.01 GHz, GeForce PCX 5750,
/// body of 17,953 vertices, dt 0.05 s).
struct DurupinarFpsRow {
  const char* sequence;
  double fps;
};
inline constexpr DurupinarFpsRow kDurupinarFps[] = {
    {"naked model", 18.020},
    {"texture-mapped outfit of 1,700 vertices", 1.574},
    {"woven outfit", 1.050},
    {"knitted outfit", 1.570},
};

}  // namespace clothbench::paper

#pragma once
// A case: the tyre, its mesh and the analyses to run, as plain data. Read from TOML by case_reader.hpp;
// units mm, N, MPa (N/mm²), N/mm³, degrees.
#include <Eigen/Dense>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tirefem/tyre/table.hpp"

namespace tirefem {

// One cord–rubber ply.
struct Ply {
  std::string name;
  double cord_modulus = 0.0;    // Young's modulus of the cord, MPa
  double cord_area = 0.0;       // cross-section area of one cord, mm²
  double ends_per_mm = 0.0;     // cords per mm of ply width (measured across the cords), 1/mm
  double angle_deg = 90.0;      // cord angle to the circumferential direction; 90 = radial, sign = hand
  double thickness = 0.0;       // ply thickness (cords + skim rubber), mm
  double rubber_modulus = 0.0;  // Young's modulus of the skim rubber, MPa
  double rubber_poisson = 0.49;
  double cord_poisson = 0.3;  // only for ν12 of the Halpin–Tsai rule (rule of mixtures)
};

enum class CordRubberRule { halpin_tsai, gough_tangorra };

// A membrane face: plies (laminated) plus an optional directly given orthotropic stiffness (which is also
// where isotropic rubber layers end up). face_stiffness() in tyre/ply_stiffness.hpp sums both.
struct FaceLayup {
  std::vector<Ply> plies;
  CordRubberRule rule = CordRubberRule::halpin_tsai;
  // A (N/mm), Voigt [11, 22, 12] with engineering shear; axis 1 meridional, axis 2 circumferential.
  std::optional<Eigen::Matrix3d> direct_stiffness;
};

// A stretch of the meridian with one construction. Runs from the previous zone's s_end (or 0) to s_end.
struct Zone {
  std::string name;
  double s_end = 0.0;                // mm from the equator
  FaceLayup inner;                   // carcass face
  FaceLayup outer;                   // breaker / sidewall face
  double core_shear_modulus = 0.0;   // interlayer transverse shear modulus, MPa
  double core_normal_modulus = 0.0;  // interlayer through-thickness modulus, MPa
};

struct TyreDescription {
  std::string name;
  std::vector<Eigen::Vector2d> profile;  // carcass line (x, r), equator (x = 0) → bead, x ≥ 0
  std::vector<Zone> zones;
  Table interlayer_thickness;        // h(s), mm: distance of the outer face from the carcass along the normal
  Table tread_height;                // hp(s), mm, measured from the outer face; only for s ≤ tread_end_s
  double tread_end_s = 0.0;          // tread edge, mm from the equator; no tread beyond
  double tread_stiffness = 0.0;      // Winkler stiffness kp, N/mm³ (per unit area of the outer face)
  double tread_shear_modulus = 0.0;  // effective tread rubber shear modulus G, MPa
};

struct MeshSettings {
  int circumferential_elements = 120;
  // Along the meridian, equator to bead: the full model has twice as many (bead to bead).
  int meridional_elements = 46;
  bool half_model = true;
  // Ratio of the element length at φ = ±π to the one at φ = 0 (the patch); 1 = uniform.
  double circumferential_refinement = 4.0;
};

struct InflationSettings {
  bool enabled = true;
  double pressure = 0.2;  // MPa
  bool linear = false;
  int max_newton_iterations = 25;
  double residual_tolerance = 1e-8;
};

struct Case {
  std::filesystem::path source;  // the file it came from (for messages and relative paths)
  std::string title;
  TyreDescription tyre;
  MeshSettings mesh;
  InflationSettings inflation;
};

}  // namespace tirefem

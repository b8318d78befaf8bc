// The axisymmetric FE specimen between the bar faces (Secs. 2.3.1-2.3.2, 2.4.2): a meshed sand
// cylinder (radius R_s, length L_s) in penalty contact with two rigid bar-face planes and a
// confining tube, implementing the specimen coupling of core/specimen_coupling.hpp.
//   Faces: the front plane sits at z = intrusion_front (moving +z), the back plane at
//   z = L_s - intrusion_back (moving -z); the face forces returned are the summed contact
//   normal forces (compression +). The faces carry no specimen mass (face_mass() = 0): the
//   specimen's own nodes carry it and meet the faces through contact.
//   Tube: none, rigid, a massless Lame spring, or a meshed linear-elastic tube (free ends).
//   Energy: specimen (and tube) kinetic energy; internal work = material work + contact normal
//   work (springs + dampers) + friction work + mass damping work. Each step checks dt against
//   the stable limit and the energy balance (held - face work - initial kinetic); a breach
//   throws NumericalError.
#pragma once
#include <optional>
#include <variant>
#include <vector>

#include "core/specimen_coupling.hpp"
#include "core/specimen_geometry.hpp"
#include "fe/body.hpp"
#include "fe/contact.hpp"

namespace kolsky::fe {

/// No confinement: the lateral surface is free.
struct NoTube {};
/// Rigid wall at r = R_s.
struct RigidTube {};
/// Massless elastic tube: a radial spring per unit wall area from the Lame solution of a
/// free-ended thick cylinder (lame_wall_stiffness), in series with the contact penalty.
struct SpringTube {
  LinearElastic material;
  double thickness = 5e-3;  ///< m (not given in Ch. 2, targets 2d)
};
/// Meshed linear-elastic tube, r in [R_s, R_s + thickness], centred on the specimen, free ends.
struct MeshedTube {
  LinearElastic material;
  double thickness = 5e-3;  ///< m (not given in Ch. 2)
  double length = 50e-3;    ///< m (Ch. 3: the steel tube is 50 mm long); >= L_s
  int n_r = 2, n_z = 25;    ///< elements through the wall and along the tube
};
using Tube = std::variant<NoTube, RigidTube, SpringTube, MeshedTube>;


struct FeSpecimenParams {
  double radius = kSpecimenDiameter / 2;  ///< R_s, m (Sec. 2.2: d = 19.1 mm)
  double length = kSpecimenLength;        ///< L_s, m (Sec. 2.2)
  int n_r = 20, n_z = 20;   ///< specimen elements (radial, axial)
  /// Specimen material; the default is the Sec. 2.3.2 elasticity (G 50 MPa, nu 0.3) without an
  /// EOS, for checks. SHPB runs pass PseudoTensorModeI with the compaction EOS.
  Material material = LinearElastic{130e6, 0.3, 1457.5};
  Tube tube = RigidTube{};
  double friction_faces = 0.0;  ///< Coulomb mu at both bar faces (Sec. 2.4.2: 0 or 0.2)
  double friction_tube = 0.0;   ///< Coulomb mu at the tube wall
  /// Penalty stiffness k = penalty_scale * M_max * (tributary area) / (element depth), M_max the
  /// specimen's steepest constrained modulus: penetration = penalty_scale^-1 of the strain the
  /// stiffest material would take over one element depth.
  double penalty_scale = 4.0;
  /// Normal contact damping, fraction of critical for each slave node on its penalty spring
  /// (c = 2 zeta sqrt(k m)); without it a node bouncing on a penalty spring gains energy.
  double contact_damping = 0.1;
  double mass_damping = 0.0;       ///< c (1/s) of c*M*v; 0 for SHPB runs, > 0 for static checks
  double energy_tolerance = 0.05;  ///< |balance error| / peak energy that stops a run
  bool check_dt = true;            ///< throw when advance(dt) exceeds the current stable dt
  /// Throw when the energy balance breaks (energy_tolerance). Off only with the run's
  /// time.check_stability = false, to let an unstable step grow until it overflows.
  bool check_energy = true;
  /// OpenMP threads for the element loop; results do not depend on it. 1 (serial) by default:
  /// on a loaded 2-core machine threads spin against other processes.
  int threads = 1;
};

/// Energy ledger of the FE specimen (J).
struct FeEnergy {
  double kinetic = 0, material_work = 0;
  double normal_work = 0;      ///< taken by the normal contact springs and dampers
  double friction_work = 0;    ///< taken by the tangential (Coulomb) contact forces
  double damping_work = 0;     ///< dissipated by mass damping
  double contact_elastic = 0;  ///< share of normal_work still stored in the springs, k g^2 / 2
  double face_work = 0;        ///< work the bar faces did on the specimen
  double initial_kinetic = 0;  ///< kinetic energy at t^0
  double held() const { return kinetic + material_work + normal_work + friction_work + damping_work; }
  double balance_error() const { return held() - face_work - initial_kinetic; }
};

/// Pieces FeSpecimen is built from, shared with the meshed-bar assembly (meshed_shpb.hpp):
/// validates p and appends the specimen block (and a meshed tube) with their parts. Throws
/// InputError.
void add_specimen_blocks(const FeSpecimenParams& p, Mesh& mesh, std::vector<Part>& parts, Block& specimen,
                         std::optional<Block>& tube);
/// The specimen's end rows against the bar faces: every node of row 0 (front) and row n_z
/// (back), penalty stiffness penalty_scale x modulus x ring area / layer depth, face friction.
void face_contact_sets(const FeSpecimenParams& p, const Block& specimen, const Nodes& nodes,
                       double modulus, ContactSet& front, ContactSet& back);
/// The specimen's outer nodes against the tube (empty for NoTube), penalty stiffness from the
/// steepest specimen modulus `modulus` (in series with the Lame wall for SpringTube).
ContactSet tube_contact_set(const FeSpecimenParams& p, const Block& specimen, double modulus);
/// Tube contact forces for the tube variant (tube_surface: the meshed tube's inner nodes).
void apply_tube_contact(const Tube& tube, ContactSet& c, Nodes& nodes, double radius,
                        const std::vector<int>& tube_surface);
/// Normal dampers, fraction zeta of critical for each slave node on its spring.
/// Absolute floor of the energy-balance check (J): the elastic energy M_max V eps^2 / 2 of the
/// specimen at a strain of 1e-9, far above round-off (a body at rest in contact holds ~1e-29 J,
/// enough to break a purely relative check) and far below any SHPB loading; an unstable mode
/// growing from round-off passes it within tens of steps.
double energy_check_floor(const FeSpecimenParams& p);
void set_contact_damping(ContactSet& c, const Nodes& nodes, double zeta);

class FeSpecimen {
 public:
  /// Throws InputError for invalid geometry, counts, materials or contact parameters.
  explicit FeSpecimen(const FeSpecimenParams& p);

  double area() const;                     ///< pi R_s^2, m^2
  double length() const { return p_.length; }
  double face_mass() const { return 0.0; }  ///< faces meet the specimen through contact
  /// Element Courant bound composed with the contact springs at the current geometry (s).
  double stable_dt() const;
  /// Internal and contact forces at t^n for the faces at t^n; returns the face forces.
  FaceForces forces(const FaceState& at_tn);
  /// Central-difference step t^n -> t^{n+1}; throws NumericalError when dt exceeds
  /// stable_dt() (check_dt), on non-finite state, or when the energy balance breaks.
  void advance(double dt);
  SpecimenEnergy energy() const;
  /// (intrusion_front + intrusion_back) / L_s, compression + (conventions.md).
  double mean_strain() const;
  bool finite() const { return body_.finite(); }

  FeEnergy energy_ledger() const;
  /// Lanczos critical dt of the linearised specimen + tube, with every contact spring closed
  /// (with_contact = true) or all open (verification).
  double critical_dt(int n_lanczos, bool with_contact) const;
  double max_penetration() const;  ///< deepest contact penetration at t^n (m)
  double face_shear() const;       ///< sum |f_t| over both faces at t^n (N)
  double wall_force() const;       ///< total radial contact force on the tube at t^n (N)
  /// Volume-weighted mean axial stress of each axial element layer, front to back
  /// (compression +, Pa): the stress uniformity along the specimen.
  std::vector<double> layer_axial_stress() const;

  const Body& body() const { return body_; }
  Body& body() { return body_; }  ///< e.g. to set initial velocities before the first step
  const Block& specimen_block() const { return specimen_; }
  const std::optional<Block>& tube_block() const { return tube_block_; }
  const ContactSet& front_contact() const { return front_; }
  const ContactSet& back_contact() const { return back_; }
  const ContactSet& tube_contact() const { return tube_; }

 private:
  std::vector<SpringStencil> springs(bool abs_weights) const;
  FeSpecimenParams p_;
  Block specimen_;
  std::optional<Block> tube_block_;
  Body body_;
  ContactSet front_, back_, tube_;
  std::vector<int> tube_surface_;  // inner tube nodes, ascending z (meshed tube)
  FaceState faces_{};
  FaceForces face_forces_{};
  double face_work_ = 0, initial_kinetic_ = 0, peak_energy_ = 0, energy_floor_ = 0;
  long n_steps_ = 0;
};

}  // namespace kolsky::fe

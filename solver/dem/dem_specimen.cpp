// DemSpecimen: the bar-coupling adapter around DemSystem (see dem_specimen.hpp).
#include "dem/dem_specimen.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "core/errors.hpp"

namespace kolsky::dem {

namespace {
Particles checked(Particles p, const SpecimenWalls& w) {
  if (!(w.length > 0)) throw InputError("", "dem.specimen.length", "must be > 0");
  if (!(w.radius > 0)) throw InputError("", "dem.specimen.radius", "must be > 0");
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3& x = p.x[i];
    if (!(x.z > 0 && x.z < w.length && std::hypot(x.x, x.y) < w.radius))
      throw InputError("", "dem.particles[" + std::to_string(i) + "]",
                       "centre outside the specimen (0 < z < L, sqrt(x^2 + y^2) < R)");
  }
  return p;
}
}  // namespace

DemSpecimen::DemSpecimen(Particles particles, std::vector<Material> materials, ContactLaw law,
                         const SpecimenWalls& walls, DemOptions options,
                         const ContactHistory& history)
    : walls_(walls),
      sys_(checked(std::move(particles), walls), std::move(materials), std::move(law), options) {
  front_ = sys_.add_plane(PlaneWall{{0, 0, 0}, {0, 0, 1}, DrivenPlane{}, walls.end_law});
  back_ = sys_.add_plane(PlaneWall{{0, 0, walls.length}, {0, 0, -1}, DrivenPlane{}, walls.end_law});
  CylinderWall tube;
  tube.radius = walls.radius;
  tube.compliance = walls.tube_compliance;
  tube.law = walls.tube_law;
  sys_.add_cylinder(tube);
  if (!history.empty()) sys_.seed_contact_history(history);
  sys_.compute_forces();
  elastic_0_ = sys_.energy().elastic;
  held_ = walls.hold_until_loaded;
  forces_0_ = {sys_.plane_force(front_), sys_.plane_force(back_)};
}

double DemSpecimen::area() const { return std::numbers::pi * walls_.radius * walls_.radius; }

FaceForces DemSpecimen::forces(const FaceState& faces) {
  faces_ = faces;
  if (held_) {
    // Nothing has pushed into the specimen yet: the grains stay as packed (v = 0) and the
    // faces feel the initial state's wall forces. An outward drift of a face (the residual
    // force pushing the bar back) does not release the hold; see docs/dem.md.
    const double t = walls_.hold_threshold;
    if (!(faces.intrusion_front > t || faces.intrusion_back > t)) {
      ++held_calls_;
      // Work of the faces on the held specimen (negative while the residual force pushes a
      // face out), so that energy() changes by exactly the faces' work while held (none when
      // the supports carry the preload: the bars then feel no force).
      if (!walls_.preload_on_supports)
        held_work_ += forces_0_.front * (faces.intrusion_front - held_faces_.intrusion_front) +
                    forces_0_.back * (faces.intrusion_back - held_faces_.intrusion_back);
      held_faces_ = faces;
      return walls_.preload_on_supports ? FaceForces{0.0, 0.0} : forces_0_;
    }
    held_ = false;
    release_faces_ = faces;
    stepping_ = false;  // no step is in progress: evaluate the forces afresh below
  }
  sys_.drive_plane(front_, faces.intrusion_front, faces.rate_front);
  sys_.drive_plane(back_, faces.intrusion_back, faces.rate_back);
  if (stepping_) {
    sys_.finish_step();
    stepping_ = false;
  } else {
    sys_.compute_forces();
  }
  const FaceForces f{sys_.plane_force(front_), sys_.plane_force(back_)};
  if (!walls_.preload_on_supports) return f;
  return {f.front - forces_0_.front, f.back - forces_0_.back};
}

void DemSpecimen::enable_breakage(const BreakageParams& p, std::uint64_t seed) {
  breakage_ = start_breakage(p, seed, sys_.particles());  // validates p, cadence included
}

std::size_t DemSpecimen::apply_due_breaks() {
  // Breaks happen here, between the forces of t^n (just evaluated by forces()) and the step
  // from t^n: the bars have the face forces of t^n already; the daughters' forces enter the
  // half kick of this step (DemSystem::edit re-evaluates them).
  if (held_ || !breakage_) return 0;
  const BreakageCadence& cadence = breakage_->params.cadence;
  if (cadence.check_period > 0) {
    // Due once the steps since the last check span the period (to the round-off of their sum).
    if (time_since_check_ < cadence.check_period * (1 - 1e-9)) return 0;
    time_since_check_ = 0;
  } else {
    if (++steps_since_check_ < cadence.check_interval) return 0;
    steps_since_check_ = 0;
  }
  return apply_breaks(sys_, *breakage_, find_breaks(sys_, *breakage_));
}

void DemSpecimen::advance(double dt) {
  if (held_) return;
  if (breakage_ && breakage_->params.cadence.check_period > 0) time_since_check_ += dt;
  sys_.begin_step(dt);
  stepping_ = true;
}

SpecimenEnergy DemSpecimen::energy() const {
  // Held: the grains are as constructed; the residual forces' work is all that has changed.
  // After the release the ledger is the system's own, which already holds that work to first
  // order (the walls moved by the same intrusions): it jumps by the second-order remainder.
  if (held_) return {0.0, held_work_};
  const DemEnergy e = sys_.energy();
  // With the preload on the supports, the faces' work on the grains is split: F0 du comes
  // from the supports, only (F - F0) du from the bars; the ledger counts the bars' share.
  const double supports = walls_.preload_on_supports
                              ? forces_0_.front * faces_.intrusion_front +
                                    forces_0_.back * faces_.intrusion_back
                              : 0.0;
  // Edits (breakage) took e.edited out: kept in the internal work so that the ledger still
  // changes by exactly the faces' work (docs/breakage.md, "Energy").
  return {e.kinetic, e.elastic - elastic_0_ + e.dissipated + e.edited - supports};
}

double DemSpecimen::mean_strain() const {
  return (faces_.intrusion_front + faces_.intrusion_back) / walls_.length;
}

}  // namespace kolsky::dem

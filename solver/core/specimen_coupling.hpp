// The interface between the bars and any specimen model (1-D column, FE mesh, DEM packing).
// The bars own the two face degrees of freedom; a specimen receives the face motion and
// returns the face forces. Every specimen type provides:
//   double area() const;  double length() const;       // initial cross-section (m^2), length (m)
//   double face_mass() const;   // mass the specimen lumps onto each face DOF (kg; 0 for walls)
//   double stable_dt() const;   // its own explicit stability limit (s)
//   FaceForces forces(const FaceState& at_tn);  // state at t^n -> face forces at t^n
//   void advance(double dt);    // interior state t^n -> t^{n+1} with those forces
//   SpecimenEnergy energy() const;  double mean_strain() const;  bool finite() const;
#pragma once

namespace kolsky {

/// Face kinematics handed to a specimen: intrusion (m) and intrusion rate (m/s) of each face,
/// positive when the face moves into the specimen.
struct FaceState {
  double intrusion_front = 0, intrusion_back = 0;
  double rate_front = 0, rate_back = 0;
};

/// Forces the specimen exerts on the two bar faces, compression positive (N).
struct FaceForces {
  double front = 0, back = 0;
};

/// Energy held by the specimen (J): kinetic plus the work done on its material so far
/// (elastic energy plus what plasticity, compaction or friction dissipated).
struct SpecimenEnergy {
  double kinetic = 0, internal_work = 0;
  double total() const { return kinetic + internal_work; }
};

}  // namespace kolsky

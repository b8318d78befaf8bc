// Classic SHPB analysis of face-referred bar waves (Gama 2004; dissertation Ch. 1, 2, 4, 5).
//   Eq. 1.1 / 4.1 / 5.10  specimen strain from the reflected wave
//   Eq. 1.2               back-face stress from the transmitted wave (4.2 and 5.11 misprint e_r)
//   Eq. 1.3               strain rate from the reflected wave
//   Eq. 1.4               equilibrium check s_i + s_r = s_t
//   Eqs. 2.11-2.13        wave energies W_i, W_r, W_t; W_loss and dissipation percentage
//   Eq. 2.15 / 4.15       stress non-uniformity alpha(t)
//   Eq. 4.16              average of front- and back-face stress
//   Eq. 5.1               strain from an applied strain-rate history
// Sign convention (docs/conventions.md): inside this module bar strains and stresses are
// compression positive; measured gauge strains (compression negative) are negated at the edge.
#pragma once
#include <vector>

#include "core/specimen_geometry.hpp"

namespace kolsky::shpb {

/// One elastic bar as the analysis sees it.
struct AnalysisBar {
  double youngs_modulus = 200e9;  ///< E_o, Pa
  double density = 8100.0;        ///< rho_o, kg/m^3
  double poisson_ratio = 0.33;    ///< for the dispersion correction only
  double diameter = kBarDiameter; ///< m
  double gauge_distance = 0.0;    ///< gauge to specimen face, m (gauge processing only)
  double wave_speed() const;
  double area() const;
};

struct AnalysisSetup {
  AnalysisBar incident, transmission;
  double specimen_length = kSpecimenLength;      ///< L_s, m
  double specimen_diameter = kSpecimenDiameter;  ///< m (A_s)
  double specimen_area() const;
};

/// Bar strains referred to the specimen faces on one uniform clock, compression positive.
/// t = 0 is the arrival of the incident wave at the incident-bar/specimen face.
struct FaceWaves {
  std::vector<double> t;      ///< s, uniform spacing
  std::vector<double> eps_i;  ///< incident strain at the front face
  std::vector<double> eps_r;  ///< reflected strain at the front face (tensile < 0)
  std::vector<double> eps_t;  ///< transmitted strain at the back face
};

/// The specimen's response, every series on FaceWaves::t.
struct SpecimenHistory {
  std::vector<double> t;
  std::vector<double> strain;              ///< Eq. 1.1 (engineering, compression positive)
  std::vector<double> strain_rate;         ///< Eq. 1.3, 1/s
  std::vector<double> strain_three_wave;   ///< from v_front - v_back = c(e_i - e_r - e_t)
  std::vector<double> strain_rate_three_wave;
  std::vector<double> stress_front;        ///< E (A_o/A_s)(e_i + e_r), Pa
  std::vector<double> stress_back;         ///< Eq. 1.2: E (A_o/A_s) e_t, Pa
  std::vector<double> stress_avg;          ///< Eq. 4.16, Pa
  std::vector<double> alpha;               ///< Eq. 2.15; NaN where |stress_avg| is below the floor
  std::vector<double> w_incident, w_reflected, w_transmitted;  ///< Eqs. 2.11-2.13, J (cumulative)
  std::vector<double> w_loss;              ///< W_i - W_r - W_t, J
  std::vector<double> dissipation_percent; ///< 100 W_loss / W_i (NaN while W_i = 0)
};

struct AnalysisOptions {
  /// alpha(t) is reported only where |stress_avg| >= alpha_floor_fraction * max|stress_avg|;
  /// below that the ratio is noise over noise (documented in docs/analysis.md).
  double alpha_floor_fraction = 0.02;
};

SpecimenHistory analyze(const FaceWaves& w, const AnalysisSetup& s, const AnalysisOptions& o = {});

/// Eq. 5.1: cumulative trapezoid integral of an applied strain rate (uniform dt).
std::vector<double> strain_from_strain_rate(const std::vector<double>& rate, double dt);

/// The direct analysis of a test without bar waves (Sec. 5.2.1, methodology 1: strain-rate
/// controlled walls): strain and strain rate as applied (Eq. 5.1), front and back stresses
/// as the wall forces over the specimen area, their average (Eq. 4.16) and alpha (Eq. 2.15,
/// with the floor of `o` relative to the record's peak |stress_avg|, as analyze() does). The
/// three-wave series and the wave energies stay empty: there are no waves. Any length,
/// including 0 and 1 (nothing here differentiates or needs a uniform clock); all inputs must
/// have the length of t (std::invalid_argument otherwise).
SpecimenHistory analyze_faces(const std::vector<double>& t, const std::vector<double>& strain,
                              const std::vector<double>& strain_rate,
                              const std::vector<double>& stress_front,
                              const std::vector<double>& stress_back, const AnalysisOptions& o = {});

/// Eqs. 2.11-2.13 for one stress series sigma (Pa) in a bar of area A, density rho, speed c:
/// cumulative W(t) = A/(rho c) * integral sigma^2 dt (trapezoid), J.
std::vector<double> wave_energy(const std::vector<double>& sigma, double dt, double area,
                                double density, double wave_speed);

/// Eq. 2.15: |front - back| / ((front + back)/2); NaN where |(front+back)/2| < floor.
double stress_nonuniformity(double stress_front, double stress_back, double floor);

/// First index at which alpha stays below `threshold` (strictly) for at least `hold`
/// consecutive samples, or -1 if it never does. NaN samples break a run; hold < 1 counts as 1.
long first_equilibrium_index(const std::vector<double>& alpha, double threshold, long hold);

/// Equilibrium quality indices used by open SHPB tools (docs/analysis.md gives the formulas and
/// sources: DynaMat-Platform validity_assessment.py; SHPB_Processing.py strain difference),
/// evaluated over samples [begin, end).
struct EquilibriumIndices {
  double force_balance = 0;        ///< FBC = 1 - mean(|F_front - F_back| / max(F_front, F_back))
  double stress_equilibrium = 0;   ///< SEQI = exp(-RMSE(front - back) / range(front))
  double mean_alpha = 0;           ///< mean of the finite alpha samples
  double max_strain_difference = 0;///< max |e_i + e_r - e_t| (Eq. 1.4 residual, bar strain)
};
EquilibriumIndices equilibrium_indices(const FaceWaves& w, const SpecimenHistory& h,
                                       long begin, long end);
/// The same from the face stresses alone (a direct analysis, analyze_faces): FBC, SEQI and
/// mean alpha; max_strain_difference is NaN (no waves, no Eq. 1.4 residual).
EquilibriumIndices equilibrium_indices(const SpecimenHistory& h, long begin, long end);

/// Least-squares slope of y against x over samples [begin, end) (e.g. constrained modulus).
double fitted_slope(const std::vector<double>& x, const std::vector<double>& y, long begin,
                    long end);

}  // namespace kolsky::shpb

// The uncertainty budget of a calibration's nine parameters, after the GUM (JCGM 100:2008).
//
// Inputs: the fit's covariance (type A: what the captures' noise and scatter leave uncertain)
// and the standard uncertainty of each reference quantity the fit takes as known (type B:
// local gravity, the turntable radius read with ruler and compass, the turntable's speed, the
// table's residual tilt after leveling, the prism's squareness).
//
// Propagation (GUM 5.1): the fit's estimate p minimizes sum_i w_i r_i(p, q)^2, with q the
// reference quantities. Its sensitivity to q is that of the weighted least-squares solution,
//   dp/dq = -(J^T W J)^-1 J^T W (dr/dq),   J = dr/dp at p, W = diag(1/sigma_i^2),
// over the fitted parameters (a held one has none), evaluated with the final model (with its
// adopted effects). dr/dq is taken by central differences of the model's own residuals, so an
// adopted effect that changes how a reference enters (a radius offset, a speed scale) is
// accounted for. Each contribution is |c| u(q); they are independent, so
//   u_c^2 = u_A^2 + sum_q (c_q u(q))^2.
// How each reference quantity enters:
//  - gravity: every capture's reference magnitude (static |f| = g; turntable sqrt(g^2+(w^2 r)^2));
//  - radius: one ruler-and-compass reading per mount, taken as one error common to every
//    turntable capture (fully correlated: the same ruler, the same method);
//  - turntable speed: a relative error common to every run (the device's tolerance);
//  - table tilt: only the turntable runs feel it, at second order: the mean specific force of a
//    run on a table tilted by t is sqrt((g cos t)^2 + (w^2 r)^2) (gravity's in-plane part
//    averages out over whole turns); with a zero first derivative the GUM's higher-order term
//    (5.1.2, note) gives u = |d2p/dt2| u(t)^2 / sqrt(2);
//  - a run's own radius (a fixture's board off the plate's reference point, its radius moved by
//    the plate's placement at each run: FitCapture::radius_own_u_m): one input per run,
//    independent; the fit weighed each run by it too, so its covariance holds it: the type A is
//    that covariance less this part, which is listed as "run's own radius";
//  - prism squareness: none: the magnitude method never uses the direction of a pose (a face
//    that is not square changes which way "up" is, not |f|), so the sensitivity is 0, listed.
// Degrees of freedom: type B inputs are taken as known to their stated uncertainty (infinite);
// type A has the fit's dof when its sigmas were scaled by sqrt(chi2/dof) (the scatter decided
// them), else infinite (each capture's noise comes from thousands of samples). The effective
// degrees of freedom follow Welch-Satterthwaite (G.4.1), the coverage factor is Student's t at
// 95.45 % (k = 2 for infinite dof, G.3), U = k u_c.
//
// Units: each parameter's own (counts, counts per m/s^2, rad); reference quantities in SI
// (m/s^2, m, rad) and the speed relative (1 = 100 %).
#pragma once

#include <string>
#include <vector>

#include "accelcal/base/sensor_model.h"
#include "accelcal/calibration/fit/fit_capture.h"
#include "accelcal/calibration/fit/fit_summary.h"
#include "accelcal/calibration/fit/residual_model.h"

namespace accelcal {

// Standard uncertainties (1-sigma) of the reference quantities; NaN: not stated (the budget
// then lists the quantity as not stated, when the captures depend on it).
struct ReferenceUncertainties {
  double gravity_mps2 = kNaN;          // local gravity, m/s^2
  double radius_m = kNaN;              // turntable radius reading, m
  double rpm_relative = kNaN;          // turntable speed, relative (0.001 = 0.1 %)
  double table_tilt_rad = kNaN;        // residual tilt of the table after leveling, rad
  double prism_squareness_rad = kNaN;  // the prism's faces off square, rad

  std::string Validate() const;  // empty when every stated value is finite and >= 0
};

// The quantity of the budget's line for the runs' own radii.
inline constexpr const char* kOwnRadiusQuantity = "run's own radius";

// One line of a parameter's budget.
struct BudgetContribution {
  std::string quantity;        // "fit (type A)", "gravity", "radius", "turntable speed", ...
  char type = 'B';             // 'A' or 'B'
  double standard_uncertainty = kNaN;  // u(q) in `quantity_unit`; NaN: not stated
  std::string quantity_unit;   // "m/s^2", "m", "1", "rad"; the parameter's unit for type A
  // c = dp/dq in the parameter's unit per `quantity_unit` (for table tilt: d2p/dt2, per rad^2);
  // 1 for type A.
  double sensitivity = kNaN;
  double contribution = kNaN;  // its part of u_c, in the parameter's unit (0 when not stated)
  double dof = kNaN;           // degrees of freedom (infinity: known)
  std::string note;            // how it enters when not plainly (second order, not used, ...)
};

struct ParameterBudget {
  int index = -1;              // ParameterIndex
  std::string name;            // "bias_x", ...
  std::string unit;            // "counts", ...
  double value = kNaN;
  std::vector<BudgetContribution> contributions;  // type A first
  double combined = kNaN;      // u_c
  double effective_dof = kNaN; // Welch-Satterthwaite; infinity when every input is known
  double coverage_factor = kNaN;
  double expanded = kNaN;      // U = k u_c
};

struct UncertaintyBudget {
  double coverage_probability = 0.9545;
  std::vector<ParameterBudget> parameters;  // the fitted ones of the nine, in ParameterIndex order
  std::vector<std::string> not_stated;      // reference quantities the captures depend on whose
                                            // uncertainty nobody stated (the budget is incomplete)

  const ParameterBudget* Find(int index) const;  // nullptr when held or absent
};

// The budget of `fit` (usable; fitted with `model` over `captures`, the ones it used, in its
// order, with local gravity `gravity_mps2`) given the reference uncertainties.
UncertaintyBudget MakeUncertaintyBudget(const ResidualModel& model,
                                        const std::vector<FitCapture>& captures,
                                        const FitSummary& fit, double gravity_mps2,
                                        const ReferenceUncertainties& references);

}  // namespace accelcal

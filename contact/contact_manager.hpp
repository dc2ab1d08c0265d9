// SPDX-License-Identifier: MIT
// The contact library's narrow API (docs/conventions.md A.4.5, after Tribol): the solver registers
// surfaces and interactions once, then calls compute_forces() every step with the current
// positions and velocities; it never reaches into the search or enforcement.
//
// Per step and per interaction pass (slave surface -> master surface; a symmetric interaction runs
// both passes, each with partition factor 1/2, docs/theory.md 5.1):
//  1. broad phase (BucketSearch) only when a surface node has moved more than `research_fraction`
//     of the search margin since the last search; the candidate faces of every slave node are kept
//     in between;
//  2. narrow phase: closest-point projection of each slave node on its candidate faces
//     (quad_projection), keeping the face over which the node projects with the smallest |gap|;
//  3. enforcement: penalty normal force f = -k_p g n for g < 0 on the slave node and -N_a f on the
//     master face nodes (momentum conserved exactly), k_p = penalty_scale m_eff / dt_ref^2 with
//     m_eff = m_s m_M / (m_s + m_M), 1/m_M = sum_a N_a^2 / m_a (docs/theory.md 5.2): with the default
//     scale 1 the node's frequency stays inside the central-difference limit at the run's time step;
//  4. interface models (contact/models/): `adhesion` adds the attractive Lennard-Jones traction
//     sigma_s(g + z0) A_I on slave nodes with 0 <= g <= g_c (nodal tributary areas A_I, shape-function
//     reactions on the master); `junction` adds to it the shear tau A_I on slave nodes in contact
//     (g <= g_j, penalty contact included), tau opposing the relative tangential velocity;
//     `rough_surface` replaces the penalty by the homogenized GW law (models/rough_surface.hpp) at the
//     mean-plane separation d = g + mean_plane_offset: normal traction p(d) A_I, shear tau* (A_c/A_0) A_I
//     by the junction law, and stable-time-step bounds per node: 2 sqrt(m_eff / (A_I dp/dd)) for the
//     normal spring, 2 m_eff v_ref / (tau* (A_c/A_0) A_I) for the shear damper.
//  5. junction shear, after the normal forces of the pass, on the in-contact part of each slave
//     node's tributary area (the gap interpolated bilinearly over each slave face and sampled 8 x 8:
//     int over {g <= g_j} of N_I dA, so the area does not jump by a ring of nodes as rings enter
//     contact); it is also the reported contact area of a junction interaction. Backward Euler in the relative tangential
//     velocity of each pair (models/junction_shear.hpp, docs/theory.md 7.3), with the velocity the pair
//     would reach without the shear predicted from the other forces, and a pair mass that counts every
//     slave sharing a master node (row sums of the pairs' coupling, so the simultaneous updates of
//     all pairs cannot overshoot: Gershgorin).
// With `enforcement = mortar` steps 2-4 are replaced by the segment-to-segment integration of
// contact/mortar/ (weighted gaps, consistent nodal loads, adhesion at face integration points).
#pragma once

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "contact/models/adhesion_lj.hpp"
#include "contact/models/junction_shear.hpp"
#include "contact/mortar/mortar_enforcement.hpp"
#include "contact/models/rough_surface.hpp"
#include "contact/search/bucket_search.hpp"
#include "contact/surface.hpp"

namespace tribex::contact {

enum class InterfaceModel { frictionless, adhesion, junction, rough_surface };

/// node_to_face: penalty on slave nodes projected on master faces (adhesion with nodal tributary
/// areas); mortar: segment-to-segment integration (contact/mortar/; models frictionless, adhesion).
enum class Enforcement { node_to_face, mortar };

struct InteractionSettings {
  std::string name;
  int slave = 0;    // index into the surfaces given to the manager
  int master = 1;
  bool symmetric = false;          // two passes, each surface slave once, factor 1/2
  double penalty_scale = 1.0;      // k_p dt^2 / m_eff
  double search_margin = 0.0;      // m; 0: the mean face edge of the master surface
  double research_fraction = 0.25; // re-search when a node moved this fraction of the margin
  InterfaceModel model = InterfaceModel::frictionless;
  AdhesionLaw adhesion;            // adhesion and junction models; the margin must be >= g_c
  JunctionLaw junction;            // junction model; rough_surface: tau* and v_ref of the shear
  Enforcement enforcement = Enforcement::node_to_face;
  std::shared_ptr<const RoughSurfaceLaw> rough;  // rough_surface model (shared by its two passes)
  double mean_plane_offset = 0.0;  // rough_surface: d = gap + offset, m
};

// Forces are those acting on the slave surfaces (for a symmetric interaction the second pass's
// forces enter with the sign of the reaction on the first slave).
struct ContactTotals {
  double normal_force = 0.0;       // net normal force on slave nodes, compressive - adhesive, N
  double tangential_force = 0.0;   // magnitude of the vector sum of junction shear forces, N
  double compressive_force = 0.0;  // sum of penalty (repulsive) normal forces, N
  double adhesive_force = 0.0;     // sum of attractive adhesion forces (positive), N
  double adhesion_energy = 0.0;    // adhesive potential sum_I A_I U(g_I) (<= 0), J
  double junction_capacity = 0.0;  // tau* x contact area (junction model), N
  double friction_power = 0.0;     // sum_I -F_t,I . (v_t^{n+1/2} + v_t^+)/2 dissipated by the junction shear, W
  double area = 0.0;               // contact area: tributary areas of slave nodes in contact (junction: in-contact face parts), m^2
  int nodes = 0;                   // slave nodes in contact (first pass of each interaction)
  double max_penetration = 0.0;    // m
  // Run guards (solver/guards/README.md): the deepest penetration in local element sizes, max over
  // slave nodes of -g / sqrt(A_I) (A_I the node's tributary area), and the largest one-step motion of
  // the surfaces against the capture distance, max over passes of dt (max|v_slave| + max|v_master|) / margin:
  // a bound on the relative normal approach per step; past 1 a node can cross the master unseen.
  double max_penetration_ratio = 0.0;
  int penetration_node = -1;       // global node of max_penetration_ratio (-1: none)
  double motion_ratio = 0.0;
  int motion_node = -1;            // global node moving fastest in the pass of motion_ratio
  double radius_max = 0.0;         // farthest contacting node from the axis (if one is set), m
  double radius_edge = 0.0;        // mean axis distance of the gap sign changes on slave-face edges, m
  double radius_pressure_fit = 0.0;  // a of the elliptic pressure p^2 = p0^2 (1 - r^2/a^2) fitted to the nodal pressures, m
  int searches = 0;                // broad-phase builds this step
  // rough_surface model (slave side, partition factor applied):
  double real_area = 0.0;          // sum A_I (A_c/A_0)(d_I), m^2
  double asperity_contacts = 0.0;  // sum A_I (N/A_0)(d_I): asperities in contact
  double nominal_area = 0.0;       // sum A_I over nodes with d_I below the contact separation, m^2
  double apparent_pressure() const { return nominal_area > 0.0 ? normal_force / nominal_area : 0.0; }
};

/// Records a penetration `depth` (m) of a slave node (global index) with tributary area `area` (m^2)
/// in the guard fields of `t`.
inline void note_penetration(ContactTotals& t, double depth, double area, int node) {
  if (!(depth > 0.0) || !(area > 0.0)) return;
  const double ratio = depth / std::sqrt(area);
  if (ratio > t.max_penetration_ratio) {
    t.max_penetration_ratio = ratio;
    t.penetration_node = node;
  }
}

class ContactManager {
 public:
  /// `mass` [node] the lumped masses; `dt_ref` the run's time step used for the penalty stiffness.
  ContactManager(std::vector<ContactSurface> surfaces, std::vector<InteractionSettings> interactions,
                 const std::vector<double>& mass, double dt_ref, int node_count);

  /// Adds contact forces at positions x [node][3] to `force` [node][3] (touching only surface
  /// nodes) and fills traction [node][3] (force / tributary area, Pa) and status [node] (1 in contact).
  /// `v` [node][3] the velocities the positions moved with (v^{n+1/2}); `other_force` [node][3] the
  /// non-contact forces of the coming velocity update and `dt` its step (0: dt_ref), used by the
  /// junction model to predict the slip the next step would have without the shear (nullptr: none).
  ContactTotals compute_forces(const double* x, const double* v, double* force, const double* other_force = nullptr,
                               double dt = 0.0);

  /// Contact axis for contact_radius_max: a point and a unit direction.
  void set_axis(const double point[3], const double direction[3]);

  const std::vector<double>& traction() const { return traction_; }
  const std::vector<double>& status() const { return status_; }
  const std::vector<int>& surface_nodes() const { return all_nodes_; }
  const std::vector<ContactSurface>& surfaces() const { return surfaces_; }
  long total_searches() const { return total_searches_; }
  /// Critical time step of the rough-surface contact at the last compute_forces: min over nodes of
  /// 2 sqrt(m_eff / k_I) (normal spring A_I dp/dd) and 2 m_eff / c_I (shear damper); INFINITY without one.
  double stable_time_step() const;

  /// Initial gaps (pre-flight report): per interaction pass, the most penetrating slave nodes.
  struct Overlap {
    std::string pass;  // "slave -> master"
    int node = -1;     // global node index
    double gap = 0.0;  // m (< 0: overlap)
  };
  std::vector<Overlap> initial_overlaps(const double* x, int worst_count);

  /// What the manager carries from one step to the next (search results, the face each slave node
  /// was over, positions at the last search, nodal outputs): saved in restart files so that a
  /// resumed run repeats the uninterrupted one bit for bit (contact/contact_manager_state.cpp).
  struct PassState {
    std::vector<int> candidate_offset, candidates, last_face;
    std::vector<double> x_at_search, gap;
    bool searched = false;
    double stable_dt = INFINITY;  // rough_surface: the contact's critical step, read before the next force pass
  };
  struct State {
    std::vector<PassState> passes;
    std::vector<double> traction, status;
    long total_searches = 0;
  };
  State state() const;
  /// Throws std::invalid_argument when `s` does not fit this manager's surfaces and passes.
  void restore(const State& s);

 private:
  struct Pass {
    int slave, master;
    double factor;
    double margin;
    double research_fraction;
    double penalty_scale;
    InterfaceModel model;
    AdhesionLaw adhesion;
    JunctionLaw junction;
    std::shared_ptr<const RoughSurfaceLaw> rough;
    double mean_plane_offset = 0.0;
    double stable_dt = INFINITY;  // rough_surface: critical step of the last compute_forces
    std::vector<int> candidate_offset, candidates;
    std::vector<double> x_at_search;  // [slave node + master node][3] positions at the last search
    bool searched = false;
    bool primary = true;
    std::vector<double> gap;  // [slave node] signed gap to the closest face over which it projects (NaN: none)
    std::vector<int> last_face;  // [slave node] face of the previous step (-1: none), tried first
    // Junction pairs of this step (sized once; junction_count of them used): slave index k, face,
    // shape functions [4], normal [3], then v_t^{n+1/2} [3] and the predicted v_t [3].
    int junction_count = 0;
    std::vector<int> junction_slave, junction_face;
    std::vector<double> junction_shape, junction_normal, junction_vt, junction_vpred;
    std::vector<double> contact_share;  // [slave node] in-contact part of its tributary area (junction), m^2
    std::unique_ptr<MortarEnforcement> mortar;  // enforcement = mortar only
    double penalty_per_area = 0.0;  // mortar k_A, Pa/m
    double capture = 0.0;           // mortar search capture: margin + 1.25 x the largest slave face diameter, m
  };
  void contact_shares(Pass& p);
  void apply_mortar(Pass& p, const double* x, double* force, ContactTotals& totals);  // mortar/mortar_pass.cpp
  double edge_radius(const Pass& p, const double* x) const;
  double pressure_fit_radius() const;
  bool needs_search(const Pass& p, const double* x) const;
  void track_motion(const Pass& p, const double* v, double dt, ContactTotals& totals) const;
  void search(Pass& p, const double* x);
  // Totals of the interface models over the passes of one step.
  struct Accumulator {
    ContactTotals& totals;
    const double* x;
    double friction[3] = {0.0, 0.0, 0.0};  // vector sum of shear forces on the (first) slave surfaces, N
  };
  void apply_interface(Pass& p, int k, int face, const double* shape, const double* normal, double gap,
                       double* force, Accumulator& acc);
  void apply_junction(Pass& p, const double* v, const double* other_force, double dt, double* force, Accumulator& acc);
  void apply_rough_surface(Pass& p, int k, int face, const double* shape, const double* normal, double gap,
                           const double* v, double* force, Accumulator& acc);
  void apply_shear(const Pass& p, const JunctionLaw& law, int node, const int* face_nodes, const double* shape,
                   const double* normal, double area, const double* v, double* f, Accumulator& acc);

  std::vector<ContactSurface> surfaces_;
  std::vector<Pass> passes_;
  std::vector<double> mass_;  // a copy: the manager outlives the set-up model in parallel runs
  double dt_ref_;
  BucketSearch bucket_;
  std::vector<double> traction_, status_;
  std::vector<double> master_share_;  // [node] sum of N_a over the junction pairs on a master node (zero between uses)
  std::vector<int> all_nodes_;
  bool has_axis_ = false;
  double axis_point_[3] = {0, 0, 0}, axis_dir_[3] = {0, 0, 1};
  long total_searches_ = 0;
  // (r^2, p^2) of the primary passes' penalty nodes this step, for radius_pressure_fit; reserved for
  // every slave node at construction, so the hot loop does not allocate.
  std::vector<double> fit_r2_, fit_p2_;
};

}  // namespace tribex::contact

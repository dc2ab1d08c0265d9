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
//  4. the interaction law (laws/, one value type per law, visited once per pass): at every projected
//     node (g >= 0, or after its penalty force) its `at_point` hook adds the law's tractions, energy,
//     contact bookkeeping and stable-step bound (adhesion: the Lennard-Jones attraction; junction and
//     Coulomb: record the node as a tangential pair; rough surface: the GW law in place of the penalty);
//  5. its `end_pass` hook, after the normal forces of the pass: the tangential force on the recorded
//     pairs, backward Euler per pair (node_to_face/tangential_pairs.hpp): junction shear on each
//     node's in-contact share of the area, Coulomb friction mu N.
// With `enforcement = mortar` steps 2-4 are replaced by the segment-to-segment integration of
// contact/mortar/ (weighted gaps, consistent nodal loads, adhesion at face integration points).
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "contact/contact_reductions.hpp"
#include "contact/contact_totals.hpp"
#include "contact/laws/contact_law.hpp"
#include "contact/mortar/mortar_enforcement.hpp"
#include "contact/node_to_face/face_bounds.hpp"
#include "contact/node_to_face/pass_view.hpp"
#include "contact/search/bucket_search.hpp"
#include "contact/surface.hpp"

namespace tribex::contact {

/// node_to_face: penalty on slave nodes projected on master faces (node_to_face/); mortar:
/// segment-to-segment integration (mortar/) for the laws that declare `mortar = true`.
enum class Enforcement { node_to_face, mortar };

struct InteractionSettings {
  std::string name;
  int slave = 0;    // index into the surfaces given to the manager
  int master = 1;
  bool symmetric = false;          // two passes, each surface slave once, factor 1/2
  double penalty_scale = 1.0;      // k_p dt^2 / m_eff
  bool force_along_axis = false;   // node to face: the penalty force along the contact axis, not the master normal
  double search_margin = 0.0;      // m; 0: the mean face edge of the master surface
  double research_fraction = 0.25; // re-search when a node moved this fraction of the margin
  ContactLaw law;                  // frictionless by default (laws/contact_law.hpp); the margin must cover its reach
  Enforcement enforcement = Enforcement::node_to_face;
};

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

  /// Nodes whose velocity is prescribed in all three components (fixed or driven): the tangential
  /// pair update takes them as given (no predicted acceleration, no share of the pair mass), so a
  /// pair on a fixed master sticks exactly. `prescribed` [node] nonzero for such nodes.
  void set_prescribed_nodes(std::vector<char> prescribed) { prescribed_ = std::move(prescribed); }

  /// Mass-scaled runs (solver/setup/mass_scaling.hpp, docs/theory.md 1.4.1): the penalty stiffness is taken
  /// from the unscaled lumped masses `unscaled_mass` [node] and the unscaled step `unscaled_dt`, as the
  /// same deck without mass scaling would have it, so that mass scaling leaves the contact stiffness
  /// (and with it the penetration and contact area) unchanged; never above s m_eff / dt_ref^2 on the
  /// scaled masses and step, the unscaled run's k dt^2 / m_eff = s (the solver gives the contact
  /// surface nodes (dt / dt_0)^2 times their unscaled mass, so that this bound does not bind: docs/theory.md
  /// 1.4.1). Without this call the penalty is s m_eff / dt_ref^2 on the masses given to the constructor.
  void set_unscaled_penalty_reference(std::vector<double> unscaled_mass, double unscaled_dt);

  /// Distributed runs (contact/README.md "Distributed contact", solver/parallel/contact_region.hpp):
  /// this rank reports the totals, search decision and motion of the nodes with `counted` [node]
  /// nonzero (the nodes it owns: every node is counted by one rank) and combines them with the other
  /// ranks' through `reductions`; it projects only the slave nodes it holds (set_present). Every pass
  /// searches afresh at the next step. `X` [node][3] the reference positions of every surface node, m.
  void distribute(std::vector<char> counted, ContactReductions* reductions, const double* X);
  /// The nodes whose positions this rank holds from the next search on ([node] nonzero: its own and
  /// its region's ghosts): only these slave nodes are projected and only master faces of these nodes
  /// searched. Set at a step whose plan_searches returned true, before compute_forces.
  void set_present(const std::vector<char>& present);
  /// Faces of every surface whose four nodes are present (all faces without set_present).
  long long present_face_count() const;
  /// Decides which passes search this step from the motion of the counted nodes since each pass's
  /// last search (the largest over the ranks); true if any pass does. compute_forces decides itself
  /// when this was not called before it.
  bool plan_searches(const double* x);
  /// How far from a rank's own surface nodes it must hold the others for its own nodes' contact forces
  /// to be complete until the next search, m: the chain of dependencies of the passes (a penalty
  /// force reaches one capture plus one face away; a tangential pass reads the normal forces and
  /// master shares of its master nodes, two more such hops), plus the motion a search allows.
  double region_reach() const;
  /// Whether each slave node is computed on its owner only (a distributed run whose passes are all
  /// node to face): the forces on other ranks' nodes are then partial sums the solver completes (the
  /// reverse ghost exchange and the shared-node sum); tangential pairs complete their nodes' normal
  /// forces and master shares mid-pass the same way (ContactReductions::complete_node_sums).
  /// Otherwise (mortar) every rank computes every slave node of its region, and its own nodes'
  /// forces are complete.
  bool owner_computes() const { return owner_computes_; }
  /// Whether this rank's region must reach around `node` (a node it holds): owner_computes(): the
  /// slave nodes it counts (a node it only holds, or a master node, needs no neighbours here: the
  /// ranks computing the slave nodes near it hold it as a ghost); otherwise every node it holds.
  bool seeds_region(int node) const { return !owner_computes_ || seeds_[node] != 0; }
  /// The nodes whose rows the passes read until the next search ([node] 1: read), valid after a
  /// compute_forces that searched: owner_computes(): the slave nodes this rank projects and the nodes
  /// of their candidate faces (the face a node was over last step is one of them); otherwise every
  /// node of the region. A distributed run refreshes only these ghost rows between searches
  /// (ContactRegion::trim); the full region is refreshed at each search, which reads it all.
  const std::vector<char>& rows_read();
  /// The slave nodes of pass `k` (its arrays' rows: gap, last face, law state), ascending: restart files
  /// written by other rank counts move them by node (solver/restart/restart_remap.hpp).
  const std::vector<int>& pass_slave_nodes(std::size_t k) const { return surfaces_[passes_[k].slave].nodes; }
  /// Its master nodes: the rows of its positions at the last search are the slave nodes', then these.
  const std::vector<int>& pass_master_nodes(std::size_t k) const { return surfaces_[passes_[k].master].nodes; }
  std::size_t pass_count() const { return passes_.size(); }
  /// No pass is mortar: every pass's state lives on its slave nodes, so a restart on another rank count
  /// can move the candidate lists of the last search by node (else every pass searches afresh).
  bool node_to_face_only() const {
    return std::none_of(passes_.begin(), passes_.end(), [](const Pass& p) { return p.mortar != nullptr; });
  }
  /// After restore() of candidate lists moved from other ranks (restart on another rank count): keeps the
  /// lists of the slave nodes this rank projects (owner computes: its counted nodes and their faces'), as a
  /// search here would have made them.
  void keep_projected_candidates();
  /// What the passes read of a node besides its position, so what a distributed run's ghost rows
  /// carry: its velocity (a law that reads velocities, or tangential pairs), its non-contact force
  /// (tangential pairs: the junction's slip prediction, contact/README.md).
  struct GhostFields {
    bool velocity = true, other_force = true;
  };
  GhostFields ghost_fields() const;
  /// Per-node state a rank must take from the node's owner when the node enters its region (the laws'
  /// state of every pass where it is a slave node): node_state_width() doubles per node.
  int node_state_width() const;
  void get_node_state(int node, double* out) const;
  void set_node_state(int node, const double* in);

  /// Contact axis the radii are measured from (radius_max, radius_edge, radius_pressure_fit): a point and a unit direction.
  void set_axis(const double point[3], const double direction[3]);

  const std::vector<double>& traction() const { return traction_; }
  const std::vector<double>& status() const { return status_; }
  /// Result fields (contact/contact_fields.cpp, docs/theory.md 12.1), at the positions `x` [node][3]
  /// of the last compute_forces. normal_pressure: out [node] = -t . n / phi, t the traction, n the unit
  /// outward normal of the node's slave surfaces (area-weighted over its slave faces whose four nodes
  /// are present) and phi the partition factor of its slave passes (1/2 symmetric, else 1; the smaller
  /// where it is a slave node of both kinds), compressive positive; 0 on nodes of no slave surface.
  /// In a distributed run a ghost row may lag by the motion since the last search (its normal
  /// only). node_gaps: out [node] the
  /// smallest gap of the node over the passes where it is a slave node (NaN: none, or no master face
  /// within the search margin).
  void normal_pressure(const double* x, std::vector<double>& out) const;
  void node_gaps(std::vector<double>& out) const;
  const std::vector<int>& surface_nodes() const { return all_nodes_; }
  const std::vector<ContactSurface>& surfaces() const { return surfaces_; }
  long total_searches() const { return total_searches_; }
  /// Contact work of this process (not kept in restart files; plain increments, so counting costs
  /// nothing in the loop). Per interaction pass and compute_forces either a full broad-phase search
  /// (BucketSearch) or a reuse of the candidate faces kept since the last one (the cheap update:
  /// only the motion check); `searches` also counts the set-up search of initial_overlaps; `pairs` the candidate (slave node, master face) pairs handed to
  /// the narrow phase (node_to_face: closest_face, which may stop at the node's face of the previous
  /// step; mortar: the segment integration), summed over passes and steps.
  struct Work {
    long long calls = 0;           // compute_forces calls (one per force evaluation)
    long long searches = 0;        // full broad-phase searches (the set-up one of initial_overlaps included)
    long long reuses = 0;          // pass-steps that kept the candidates of an earlier search
    long long pairs = 0;           // candidate node-face pairs evaluated
    // Over the ranks, summed over the evaluations: the busiest rank's pairs and all ranks' pairs
    // (one rank: both its own). balance() = busiest x ranks / all: 1 when the work is shared evenly,
    // the rank count when one rank has it all (a contact zone on one rank: solver/README.md
    // "Parallel runs", `begin decomposition`).
    double busiest_pairs = 0.0, all_pairs = 0.0;
    double balance(int ranks) const { return all_pairs > 0.0 ? busiest_pairs * ranks / all_pairs : 1.0; }
  };
  const Work& work() const { return work_; }
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
    double stable_dt = INFINITY;  // the law's critical step (rough surface), read before the next force pass
    std::vector<double> law_state;  // the law's state per slave node (Coulomb: sliding)
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
    bool force_along_axis = false;  // InteractionSettings::force_along_axis (needs the axis set)
    ContactLaw law;
    double stable_dt = INFINITY;  // the law's critical step of the last compute_forces
    std::vector<int> candidate_offset, candidates;
    std::vector<double> x_at_search;  // [slave node + master node][3] positions at the last search
    bool searched = false;
    signed char search_due = -1;  // plan_searches' decision for this step (-1: not planned)
    double fastest[2] = {0.0, 0.0};   // this step's largest squared speed of the counted slave, master nodes, m^2/s^2
    int fastest_node[2] = {-1, -1};
    bool primary = true;
    std::vector<double> gap;  // [slave node] signed gap to the closest face over which it projects (NaN: none)
    std::vector<int> last_face;  // [slave node] face of the previous step (-1: none), tried first
    // Narrow-phase shortcuts (closest_face.hpp; same answers, so not in restart files): the master's
    // face bounds of this step and [slave node] the node's answer of the previous step (-1: none).
    FaceBounds face_bounds;
    std::vector<int> nearest_face;
    TangentialPairs pairs;       // laws with tangential forces (junction, Coulomb)
    std::vector<double> law_state;  // [slave node][state_size] the law's state
    std::unique_ptr<MortarEnforcement> mortar;  // enforcement = mortar only
    double penalty_per_area = 0.0;  // mortar k_A, Pa/m
    double capture = 0.0;           // mortar search capture: margin + 1.25 x the largest slave face diameter, m
  };
  /// Steps 2-5 for one pass (node_to_face/node_to_face_pass.cpp): the law is visited once, the loop
  /// over slave nodes is templated on it.
  struct StepInputs {
    const double* x;
    const double* v;
    const double* other_force;
    double dt;
    double* force;
  };
  void node_to_face(Pass& p, const StepInputs& in, ContactTotals& totals, double friction[3]);
  template <class Law>
  void node_to_face_with(const Law& law, Pass& p, const StepInputs& in, ContactTotals& totals, double friction[3]);
  void apply_mortar(Pass& p, const double* x, double* force, ContactTotals& totals);  // mortar/mortar_pass.cpp
  double edge_radius(const Pass& p, const double* x) const;
  double pressure_fit_radius() const;
  double motion_since_search(const Pass& p, const double* x) const;
  void track_motion(Pass& p, const double* v) const;
  void search(Pass& p, const double* x);
  void reduce_totals(ContactTotals& totals, double friction[3], long long step_pairs);
  bool counts(int node) const { return counted_.empty() || counted_[node] != 0; }

  std::vector<ContactSurface> surfaces_;
  std::vector<Pass> passes_;
  std::vector<double> mass_;  // a copy: the manager outlives the set-up model in parallel runs
  double dt_ref_;
  // Mass-scaled runs only (set_unscaled_penalty_reference; empty otherwise): the unscaled lumped
  // masses [node], kg, and step, s, the penalty is taken from.
  std::vector<double> penalty_mass_;
  double penalty_dt_ = 0.0;
  /// k_p of a node-to-face point for penalty scale `scale`, N/m (docs/theory.md 5.2, 1.4.1).
  double penalty_stiffness(double scale, const ContactPoint& point) const;
  BucketSearch bucket_;
  std::vector<double> traction_, status_;
  std::vector<char> prescribed_;  // [node] velocity prescribed in x, y, z (set_prescribed_nodes)
  std::vector<double> master_share_;  // [node] sum of N_a over the junction pairs on a master node (zero between uses)
  std::vector<int> all_nodes_;
  // Distributed runs only (distribute, set_present; empty otherwise): [node] counted here, present here.
  std::vector<char> counted_, present_;
  // owner_computes(): [node] the slave nodes this rank projects, its counted ones and the nodes of
  // slave faces with a counted node (their gaps only, for the edge radius when an axis is set).
  bool owner_computes_ = false;
  std::vector<char> projected_;
  std::vector<char> seeds_;  // owner_computes(): [node] counted slave nodes (seeds_region)
  std::vector<char> read_;   // rows_read's answer, kept: sized once
  // owner_computes() with tangential pairs: scratch of the pairs' completed forces and master shares
  // [node][4] (PassView::completion); empty otherwise.
  std::vector<double> completed_;
  ContactReductions* reductions_ = nullptr;
  UncountedTotals uncounted_;
  std::vector<double> plan_;    // [pass] scratch of plan_searches
  // Scratch of reduce_totals: the maxima (penetration, radius, each pass's stable step; no node) and
  // the located maxima (penetration ratio, each pass's fastest slave and master), one reduction.
  std::vector<double> located_value_;  // [4 + 3 pass]
  std::vector<int> located_node_;
  double largest_face_diameter_ = 0.0;  // over every surface in the reference positions, m (region_reach)
  Axis axis_;
  long total_searches_ = 0;
  Work work_;
  // (r^2, p^2) of the primary passes' penalty nodes this step, for radius_pressure_fit; reserved for
  // every slave node at construction, so the hot loop does not allocate.
  std::vector<double> fit_r2_, fit_p2_;
};

}  // namespace tribex::contact

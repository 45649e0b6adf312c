// Cutter locations for a helical surface machined with a disc cutter, by the minimum directed
// distance (seed 004): for each workpiece phase psi, the cutter is moved along X (the final
// motion) until it first touches the helicoid; the point of minimum directed distance is the
// contact. Frame: workpiece axis Z, cutter centre on +X at centre distance A.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

#include "helicoid/cutter.hpp"
#include "helicoid/profile.hpp"

namespace ncurve::helicoid {

using Vec3 = std::array<double, 3>;

struct Workpiece {
  EndProfile profile;
  double lead = 0;  // mm per turn; 0 = straight (no twist)
  int hand = 1;     // +1 right hand, -1 left hand
  int lobes = 1;    // symmetry of the profile: A repeats every 360/lobes degrees of psi
  // Degrees the end section turns per mm of Z.
  double twist() const { return lead == 0 ? 0 : hand * 360 / lead; }
};

// How the cutter sits: its axis lies in the YZ plane, the disc plane turned from the workpiece
// axis by `swing` degrees (the helix angle at the reference radius, tan swing = 2 pi r / lead).
// The crossing angle of the two axes is 90 - swing.
struct Setting {
  double swing = 0;
  double start_distance = 0;  // A at which the search starts (must be free of the workpiece), mm
};

double helix_angle(double lead, double radius);  // degrees from the axis; 0 for a straight workpiece

// The search lattice on the cutter: angle alpha around the cutter axis (0 points at the workpiece
// axis) by alpha_step degrees within +-alpha_max, and arc length s along the axial profile.
struct Lattice {
  double alpha_step = 0.05, s_step = 0.05, alpha_max = 30;
  std::int64_t size(double profile_length) const;
};
// The most lattice points a search takes (the robust search keeps a few numbers per point: about
// 40 bytes each); the default lattice of seed 004 has 1.4 million.
constexpr std::int64_t kMostLatticePoints = 20'000'000;

enum class Method { brute, nine_point, robust };
Method method_from_name(const std::string& name);
const char* method_name(Method m);

struct Contact {
  double psi = 0;         // workpiece phase, degrees
  double A = 0;           // centre distance, mm
  double alpha = 0, s = 0;  // cutter point: angle about its axis (deg), arc length on its profile (mm)
  std::string region;     // cutter profile element ("corner", "flank-", "flank+"; "flank-/flank+" on the edge between two)
  Vec3 cutter_point{};    // world frame, mm
  Vec3 work_point{};      // the contact on the workpiece, world frame at phase psi
  double u = 0;           // profile parameter of the contact, degrees
  double r = 0;           // its radius from the workpiece axis, mm
  double normal_angle = 0;  // between the surfaces' normals at the contact, degrees (0 = meshing; on
                            // an edge of the cutter, to the nearest of its normals there)
  std::int64_t evaluations = 0;  // directed-distance evaluations of the search
  double plane_A = 0;     // plane-programming centre distance (offset end profile), mm
  double z = 0;           // cutter centre's Z at the contact (0 when the final motion is X), mm
  double phase = 0;       // psi + 360 z / lead (signed by hand): the same contact with the cutter at Z = 0
};

// The final motion along Z instead of X: the cutter stands at a fixed centre distance, starts
// clear at `start_z` and travels along Z (direction -1 or +1) until it first touches. Without a
// start it starts at Z = 0, or where it is clear nearest behind 0 (the touch is then where it
// enters the workpiece around Z = 0).
struct AxialMotion {
  double centre_distance = 0;  // mm
  std::optional<double> start_z;
  int direction = -1;
};

class ContactSearch {
public:
  ContactSearch(Workpiece work, DiscCutter cutter, Setting setting, Lattice lattice);

  // Directed distance from the start position along -X, with its gradient in (alpha deg, s mm);
  // +inf where the cutter point's line misses the workpiece. Counts one evaluation.
  struct Distance {
    double d = 0;
    double d_alpha = 0, d_s = 0;
    bool hit = false;
    double x_hit = 0, u = 0;
    Vec3 q{};         // cutter point
    Vec3 n_work{};    // unit outward normal of the workpiece at the hit
    Vec3 n_cutter{};  // unit outward normal of the cutter at q
  };
  Distance distance(double psi, double alpha, double s) const;

  // Called with the number of phases done after each (progress on a terminal).
  using StepDone = std::function<void(std::size_t)>;
  // Contacts for each phase (degrees), in order; the tracing prediction follows the order.
  std::vector<Contact> run(const std::vector<double>& psis, Method method, const StepDone& done = {}) const;

  // Contacts when the final motion is along Z. A screw motion leaves the helicoid where it is, so
  // the cutter at Z = z and phase psi touches as it does at Z = 0 and phase psi + twist z: the
  // first touch along Z is the first phase, going the way the travel turns it, at which A(phase)
  // reaches the centre distance (a traced table of A over one lobe, then Illinois on the bracket).
  // Throws, naming psi, when the start is not clear or the cutter never reaches the workpiece.
  std::vector<Contact> run_axial(const std::vector<double>& psis, Method method, const AxialMotion& motion,
                                 const StepDone& done = {}) const;

  // Plane programming (the method seed 004 improves on): the end profile offset by the corner
  // radius, the cutter's corner centre placed on it along X.
  double plane_distance(double psi) const;

  // At a contact on an edge of the cutter (a convex joint without a common tangent, at angle
  // alpha about its axis), the angle between the workpiece's normal and the nearest of the
  // cutter's normals there (those fanning from the normal before the joint to the one after):
  // 0 where the workpiece's tangent plane supports the edge. Degrees.
  double edge_normal_angle(const DiscCutter::Vertex& v, double alpha, const Vec3& n_work) const;

  // Every cutter point at least `tol` clear of the workpiece at centre distance A? Returns the
  // deepest penetration found (<= 0 when clear) by a scan of the whole cutter with local descent.
  double deepest_penetration(double psi, double A, std::int64_t* evaluations = nullptr) const;

  // Material one pass leaves over the profile point u: the distance from the helix through it
  // (the path the screw motion moves it along) to the cutter standing at the pass's A and psi,
  // i.e. the distance from the design surface to what the pass cuts; < 0 where it cuts too deep.
  double stock(const Contact& pass, double u) const;

  // The highest material two passes leave on the profile between their contacts (each point's
  // stock from the nearer pass; any other pass can only lower it).
  struct Cusp {
    double height = 0;  // mm
    double u = 0;       // profile parameter of the top, degrees
  };
  Cusp cusp(const Contact& a, const Contact& b) const;

  // The fewest of the given contacts (in order, first and last kept) whose neighbours leave cusps
  // within `tol`: greedy, each pass followed by the farthest one within the tolerance. Throws,
  // naming the phases, when two neighbouring contacts already leave more.
  struct PassPlan {
    std::vector<std::size_t> passes;  // indices into the contacts
    std::vector<Cusp> cusps;          // between passes k and k + 1
  };
  PassPlan fewest_passes(const std::vector<Contact>& contacts, double tol) const;

  const Workpiece& workpiece() const { return work_; }
  const DiscCutter& cutter() const { return cutter_; }
  const Setting& setting() const { return setting_; }
  const Lattice& lattice() const { return lattice_; }
  int alpha_cells() const { return na_; }  // lattice index i in [-na, na]
  int s_cells() const { return ns_; }      // lattice index j in [0, ns]

private:
  friend class StepSearch;
  Workpiece work_;
  DiscCutter cutter_;
  Setting setting_;
  Lattice lattice_;
  Vec3 e2_{}, axis_{};  // disc-plane direction normal to X, and the cutter axis
  int na_ = 0, ns_ = 0;
  double corner_radius_ = 0;
  EndProfile plane_profile_;  // offset by the corner radius
};

}  // namespace ncurve::helicoid

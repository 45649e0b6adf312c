// What `ncurve helicoid` writes: the contact table (CSV, JSON), a 4-axis FANUC program and a plot.
#pragma once
#include <string>
#include <vector>

#include "helicoid/contact.hpp"

namespace ncurve::helicoid {

struct Job {
  std::string title;  // e.g. "seed004 rotor, lead 860 mm right hand, cutter D252 r1.2 35 deg"
  Method method = Method::robust;
  double step = 1;    // psi step, degrees
  std::string final_motion = "x";  // x, z- or z+
  std::vector<Contact> contacts;
  std::vector<double> cusps;  // material left between the passes of steps i and i + 1, mm
  // The program's passes (indices into contacts; empty: one per step) and the cusp tolerance
  // they were chosen for (0: none).
  std::vector<std::size_t> passes;
  double pass_tolerance = 0;
};

std::string contacts_csv(const Job& job);
std::string contacts_json(const Job& job, const ContactSearch& search);
std::string contacts_text(const Job& job, const ContactSearch& search);

struct PassOptions {
  int program_number = 4004;
  double z_start = 0, z_end = -100;  // each pass runs along Z between these, mm
  double feed = 200;                 // mm/min along the pass
  double clearance = 5;              // X retract above the largest A between passes, mm
};
// One helical pass per psi step, or per chosen pass (X at A(psi), A and Z tied by the lead),
// passes alternating in direction. Runs under `ncurve run` with a profile that has axes X, Z and A.
std::string pass_program(const Job& job, const ContactSearch& search, const PassOptions& options);

// End profile with the contact points, A(psi), and the plane method's error against it.
std::string contacts_svg(const Job& job, const ContactSearch& search);

}  // namespace ncurve::helicoid

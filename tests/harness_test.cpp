// The harness's own vocabulary: the claimed-bounds reader rejects every
// malformed file with its line, and each input family lands where it says.
#include <sstream>

#include "harness.hpp"

namespace contact::testing {
namespace {

std::string parse_error(const std::string& text) {
  std::istringstream in(text);
  try {
    harness::claimed_bounds::parse(in, "bounds.txt");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

const std::string all_branches =
    "free 0\nimpact 6\ncontact 3 # a comment\n\nrelease_u_positive 6.5\nrelease_u_nonpositive 4.5\n";

TEST(ClaimedBounds, ReadsEveryBranchAndTheLargest) {
  std::istringstream in(all_branches);
  const auto bounds = harness::claimed_bounds::parse(in, "bounds.txt");
  EXPECT_EQ(bounds.for_case(contact_case::contact, true), 3);
  EXPECT_EQ(bounds.for_case(contact_case::release, true), 6.5);
  EXPECT_EQ(bounds.for_case(contact_case::release, false), 4.5);
  EXPECT_EQ(bounds.largest(), 6.5);
}

TEST(ClaimedBounds, NamesTheFileAndLineOfEachMistake) {
  EXPECT_EQ(parse_error(all_branches + "impact 7\n"), "bounds.txt:7: branch 'impact' is given twice");
  EXPECT_EQ(parse_error("free\n"), "bounds.txt:1: 'free' has no bound");
  EXPECT_EQ(parse_error("free 0 1\n"), "bounds.txt:1: expected 'branch ulps', found a third field '1'");
  EXPECT_EQ(parse_error("# c\nrelease 3\n"), "bounds.txt:2: unknown branch 'release'");
  EXPECT_EQ(parse_error("free -1\n"), "bounds.txt:1: '-1' is not a finite, non-negative number of ulps");
  EXPECT_EQ(parse_error("free inf\n"), "bounds.txt:1: 'inf' is not a finite, non-negative number of ulps");
  EXPECT_EQ(parse_error("free 0\n"), "bounds.txt: no bound for branch 'impact'");
  EXPECT_NE(harness::project_bounds().largest(), 0);
}

// Each family draws inputs of the region it names (docs/equations.md,
// "Where the closed form is hard"), in every case it claims.
TEST(Families, EachLandsInTheRegionItNames) {
  using harness::distribution;
  using shape = distribution::shape;
  harness::seeded_source source(7);
  const distribution dy{shape::log10, -8, -2, 1}, phi{shape::log10, -3, 6, 1};
  for (int i = 0; i < 1000; ++i) {
    const auto free_impact = harness::free_impact_boundary<double>(source, dy, phi, 4);
    EXPECT_LE(free_impact.dy, 0);
    EXPECT_LE(std::fabs(free_impact.u + free_impact.dy), 4 * std::numeric_limits<double>::epsilon() * -free_impact.dy);
    const auto contact_release = harness::contact_release_boundary<double>(source, dy, phi, 4);
    EXPECT_GT(contact_release.dy, 0);
    const auto grazing = harness::impact_grazing<double>(source, dy, phi, {shape::log10, -9, -1, 1});
    EXPECT_EQ(solve_stable(grazing.u, grazing.dy, grazing.phi).which, contact_case::impact);
    const auto cancelling = harness::contact_cancellation<double>(source, dy, phi, {shape::log10, -12, -2, 0}, 0);
    const auto in_contact = solve_stable(cancelling.u, cancelling.dy, cancelling.phi);
    EXPECT_LE(std::fabs(in_contact.s), 2e-2 * cancelling.dy * cancelling.phi);
    const auto releasing = harness::release_cancellation<double>(source, dy, {shape::log10, 6, 12, 1}, {shape::log10, 1, 3, 1});
    EXPECT_EQ(solve_stable(releasing.u, releasing.dy, releasing.phi).which, contact_case::release);
    const auto physical = harness::physical<double>(source, harness::audio_rate());
    EXPECT_LE(std::fabs(physical.dy), 1e-3);
    EXPECT_GE(physical.phi, 1e5 / (2 * (2 * 1e-2 * 44100.0 * 44100.0 + 1e4 / 2)) / 2);
  }
}

}  // namespace
}  // namespace contact::testing

// The Vessels section's list bookkeeping: where a tracer outcome goes in the path list, new paths'
// names, and paths read from a file (no control points: not re-traced).
#include "gui/vessel_trace_job.h"

#include <gtest/gtest.h>

namespace angio {
namespace {

VesselPath path(const std::string& name, int controlPoints) {
  VesselPath p{name, {}, {name, {{{0, 0, 0}, 1}, {{0, 0, 5}, 1}}}};
  for (int n = 0; n < controlPoints; ++n) p.controlPointsMm.push_back({0, 0, 5.0 * n});
  return p;
}

TraceOutcome outcomeFor(TraceAction action, int at, std::vector<VesselPath> paths) {
  TraceOutcome outcome;
  outcome.request.action = action;
  outcome.request.path = at;
  outcome.paths = std::move(paths);
  return outcome;
}

TEST(VesselTraceJob, AnOutcomeReplacesItsPathOrIsAppended) {
  const std::vector<VesselPath> list = {path("path 1", 2), path("path 2", 2)};
  const auto replaced = withOutcome(list, outcomeFor(TraceAction::addPoint, 1, {path("path 2", 3)}));
  ASSERT_EQ(replaced.size(), 2u);
  EXPECT_EQ(replaced[1].controlPointsMm.size(), 3u);
  const auto added = withOutcome(list, outcomeFor(TraceAction::addPoint, -1, {path("path 3", 1)}));
  ASSERT_EQ(added.size(), 3u);
  EXPECT_EQ(added[2].name, "path 3");
  // A path that went meanwhile (deleted, undone): the outcome is kept as a new path.
  EXPECT_EQ(withOutcome(list, outcomeFor(TraceAction::movePoint, 7, {path("x", 2)})).size(), 3u);
  // A tree joins the list whole, whatever path was selected.
  const auto tree =
      withOutcome(list, outcomeFor(TraceAction::downstream, 0, {path("tree 1", 0), path("tree 2", 0)}));
  ASSERT_EQ(tree.size(), 4u);
  EXPECT_EQ(tree[0].name, "path 1");
  EXPECT_TRUE(withOutcome(list, outcomeFor(TraceAction::addPoint, 0, {})) == list);  // a problem
}

TEST(VesselTraceJob, NewPathsTakeTheLowestFreeNumberAndFilePathsHaveNoControlPoints) {
  EXPECT_EQ(newPathName({}), "path 1");
  EXPECT_EQ(newPathName({path("path 1", 2), path("path 3", 2)}), "path 2");
  Centerlines file;
  file.paths = {{"aorta", {{{1, 2, 3}, 10}, {{1, 2, 9}, 10}}}};
  const std::vector<VesselPath> imported = importedPaths(file);
  ASSERT_EQ(imported.size(), 1u);
  EXPECT_EQ(imported[0].name, "aorta");
  EXPECT_TRUE(imported[0].controlPointsMm.empty());
  EXPECT_EQ(imported[0].centerline, file.paths[0]);
}

}  // namespace
}  // namespace angio

// dressing-f8: dressing paper Fig. 8, time per iteration against cloth vertices.
#include "experiment_list.hpp"
#include "paper_tables.hpp"

namespace clothbench {

namespace {

using namespace paper_tables;

void dressing_f8(ExperimentContext& ctx) {
  const std::vector<int> sizes = ctx.quick() ? std::vector<int>{500, 1000, 2000}
                                             : std::vector<int>{500, 1000, 2000, 3500, 5000, 8000, 12000, 20000};
  const long iterations = ctx.quick() ? 10 : 100;
  MarkdownTable t({"collider", "vertices", "ms/iteration", "CD&R ms", "CS ms", "inside [%] after the run"});
  MarkdownTable fit({"collider", "intercept [ms]", "slope [ms per 1000 vertices]", "R^2"});
  nlohmann::json series = nlohmann::json::array();
  for (const auto& c : ctx.colliders(kAll)) {
    std::vector<double> x, y;
    for (int n : sizes) {
      std::vector<std::string> sets{"garment.vertices=" + std::to_string(n), "stop.sew=false", "stop.settle_speed=0",
                                    "stop.max_iterations=" + std::to_string(iterations)};
      for (const auto& o : papers_detection(c)) sets.push_back(o);  // the papers' detection, as the paper tables
      const RunResult& r = ctx.run("dressing/dress.toml", c, sets);
      x.push_back(r.vertices);
      y.push_back(r.ms_per_iteration());
      t.row({c, std::to_string(r.vertices), num(r.ms_per_iteration(), 3), num(r.cdr_ms_per_iteration(), 3),
             num(r.cs_ms_per_iteration(), 3), r.divergence ? "diverged" : num(r.accuracy.inside_pct, 2)});
      ctx.add_run(r, "dressing-f8/dress-" + std::to_string(n) + "/" + c);
    }
    double a = 0, b = 0, r2 = 0;
    linear_fit(x, y, a, b, r2);
    fit.row({c, num(a, 3), num(1000 * b, 3), num(r2, 4)});
    series.push_back({{"label", c + " (R² " + num(r2, 3) + ")"}, {"x", x}, {"y", y}});
  }
  ctx.chart("dressing-f8", {{"title", "Time per iteration vs cloth vertices (dress, draping)"},
                            {"xlabel", "cloth vertices"},
                            {"ylabel", "ms per iteration (log scale)"},
                            {"logy", true},
                            {"series", series}});
  ctx.write("dressing-f8", "Dressing paper Fig. 8: time per iteration vs cloth vertices",
            "The dress meshed at " + std::to_string(sizes.size()) +
                " sizes, placed and draped (gravity, no sewing) for " + std::to_string(iterations) +
                " iterations; ms per iteration = CD&R + CS. The paper shows a straight "
                "line (O(n)) for its IS method and gives no numbers; a linear fit per collider. Image space runs the "
                "papers' own test (the z comparison on 8-bit maps), fcl and embree respond with face normals "
                "(papers_detection).\n\n" +
                fit.str() + "\n![chart](dressing-f8.png)\n\n" + t.str());
}

}  // namespace

void add_dressing_f8_experiments(std::vector<Experiment>& out) {
  out.push_back({"dressing-f8", "Dressing paper Fig. 8", dressing_f8});
}

}  // namespace clothbench

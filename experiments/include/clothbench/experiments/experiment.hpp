#pragma once
/// The experiments of `clothbench reproduce`: each writes results/ID.md (our figures beside the
/// papers'), results/ID.json (Google Benchmark layout) and its charts and pictures.
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "clothbench/bench/registry.hpp"
#include "clothbench/bench/runner.hpp"
#include "clothbench/experiments/markdown_table.hpp"
#include "clothbench/experiments/statistics.hpp"
#include "clothbench/render/picture.hpp"

namespace clothbench {

/// The solver regimes the reproduction tables report side by side: ours, then the papers' clock.
inline constexpr const char* kRegimes[] = {"stable", "papers"};
/// What names a run in a regime other than the stable one: SEP + regime (rows, pictures); empty for stable.
inline std::string regime_suffix(const std::string& regime, const std::string& sep) {
  return regime == "stable" ? "" : sep + regime;
}

/// The paper tables run image space with the papers' own test by default: the z comparison along the view
/// axis (dressing Eq. 9, walking Eq. 12) on 8-bit colour maps (dressing Eqs. 6-7, walking Eqs. 9-10); rows named
/// "ours" run our default (the tangent-plane refinement on float maps). Empty for any other collider.
inline std::vector<std::string> papers_image_space(const std::string& collider) {
  const std::optional<ColliderInfo> c = collider_info(collider);
  if (!c || c->family != Family::kImageSpace) return {};
  return {"collider.tangent_plane=false", "collider.float_maps=false", "collider.layers=1"};
}

/// The paper tables' default for every collider: image space as papers_image_space, and the object-space
/// colliders that offer it (ColliderInfo::face_normals) respond with face normals, as the dressing paper's
/// bounding-box method did (section 7); rows named "ours" run our defaults (interpolated vertex normals). Empty for
/// the others.
inline std::vector<std::string> papers_detection(const std::string& collider) {
  const std::optional<ColliderInfo> c = collider_info(collider);
  if (c && c->family == Family::kObjectSpace && c->face_normals) return {"collider.face_normals=true"};
  return papers_image_space(collider);
}

/// The image-space collider the experiments lean on (built in every configuration): the ablations, the pictures
/// and the claims are its runs.
inline constexpr const char* kLeadImageSpace = "is-cpu";
/// The object-space collider the verdicts lean on (exact): where a table sets one object-space collider against
/// the others, or against image space, this one.
inline constexpr const char* kLeadObjectSpace = "embree";

/// The colliders the results tables list (ColliderInfo::in_tables), of every family.
inline ColliderFilter in_tables() {
  return [](const ColliderInfo& c) { return c.in_tables; };
}
/// The colliders the results tables list of one family.
inline ColliderFilter in_tables(Family family) {
  return [family](const ColliderInfo& c) { return c.in_tables && c.family == family; };
}
/// The colliders the tables of speed on the walking body list (walking-t2, colliders): those of every table, and
/// those that draw on a GPU, whose speed is what they are for.
inline bool in_speed_tables(const ColliderInfo& c) { return c.in_tables || c.needs == Needs::kGpu; }
/// `names` with `lead` moved to the front where it is among them (the others keep their order).
std::vector<std::string> lead_first(const std::string& lead, std::vector<std::string> names);

/// The summary a results page opens with: "**Summary.**" and one "- " line each, then a blank line ("" for no
/// lines). More than five lines is a logic error: a summary is the paper's figure, ours, the verdict.
std::string markdown_summary(const std::vector<std::string>& lines);

/// What an experiment may use: cached scene runs, output writers, the options of the command.
class ExperimentContext {
 public:
  ExperimentContext(std::string out_dir, bool quick, int repetitions, int jobs = 1);

  /// One run() request.
  struct Request {
    std::string scene, collider;
    std::vector<std::string> sets;
    RunOptions options = {};  ///< as run() is given them (measure_frames); progress is off in workers
  };
  /// With jobs > 1, runs the requests not yet cached in up to `jobs` worker processes (forked, one per
  /// request, its repetitions inside) and caches what they measured, so that run() answers them at once;
  /// with jobs = 1 it does nothing (run() runs them as asked). Prefetched results carry the cloth's end
  /// state (mesh positions and quads: the drape error) but not the body's (final_body is empty). A request that fails
  /// in its worker stays uncached, and run() then reports its error as usual.
  void prefetch(const std::vector<Request>& requests);
  /// Whether a collider draws with OpenGL: prefetch leaves its requests to run() in this process (a forked
  /// child cannot use the OSMesa state it inherits once this process has drawn).
  static bool needs_opengl(const std::string& collider);

  /// Runs scenes/SCENE (relative to the source tree's scenes/) with a collider and overrides;
  /// identical requests in one `reproduce` share one run. With repetitions > 1 the run is
  /// repeated and the repetition with the median time per iteration is returned; add_run() writes
  /// every repetition's row and the aggregates. `at_least`: repeat it so many times even without --repetitions
  /// (timings that a verdict rests on); a request cached with fewer runs is run again until it has them (the
  /// results returned before for it may then move: ask run() again).
  const RunResult& run(const std::string& scene, const std::string& collider, const std::vector<std::string>& sets = {},
                       const RunOptions& options = {}, int at_least = 1);
  /// Every repetition of the request that returned `r` (r alone when it is not one of run()'s).
  std::vector<const RunResult*> repetitions_of(const RunResult& r) const;
  /// Colliders of `wanted` that this build has (the others are reported as not built): a deliberate selection.
  std::vector<std::string> colliders(const std::vector<std::string>& wanted) const;
  /// The built colliders `keep` accepts, in registry order (those it accepts that are not built are reported as
  /// not built): every collider of a kind, a registered one included.
  std::vector<std::string> colliders(const ColliderFilter& keep) const;
  /// Adds a JSON row for the current experiment (measurements not made by run()).
  void add_row(nlohmann::json row) { rows_.push_back(std::move(row)); }
  /// Adds the rows of a run() result named `name`, `extra` fields merged into each: with repetitions,
  /// one row per repetition and their aggregates (repetition_rows), else result_row(r, name).
  void add_run(const RunResult& r, const std::string& name, const nlohmann::json& extra = nlohmann::json::object());
  /// Writes OUT/ID.md (title, `summary`, definitions, machine, `body`) and OUT/ID.json (rows so far). The
  /// summary opens the page: at most five lines (the paper's figure, ours, the verdict, the row that answers
  /// it), each computed from this run's data; more than five is a logic error.
  void write(const std::string& id, const std::string& title, const std::string& body,
             const std::vector<std::string>& summary = {});
  /// Renders a chart through experiments/plot/plot.py (matplotlib) into OUT/NAME.png; `spec` holds
  /// title, xlabel, ylabel, series [{label, x, y}], optional logx/logy. Returns false (and says
  /// why on stderr) when python3/matplotlib are missing.
  bool chart(const std::string& name, nlohmann::json spec);
  /// OUT/relative, creating its folder.
  std::string path(const std::string& relative) const;
  /// The folder OUT/relative, created.
  std::string folder(const std::string& relative) const;

  bool quick() const { return quick_; }
  /// reproduce --jobs: worker processes for prefetched grids (1: every run in this process).
  int jobs() const { return jobs_; }
  /// One sentence for a grid experiment's page: how its grid ran (worker processes at once, or one by one).
  std::string grid_note(std::size_t runs) const;
  /// The renderer of every picture of this `reproduce` (the build's default backend), created on first use
  /// and kept: one OSMesa context for all pictures. Throws as make_picture_renderer does.
  PictureRenderer& pictures();

 private:
  std::string out_dir_;
  bool quick_;
  int repetitions_;
  int jobs_;
  std::map<std::string, std::vector<RunResult>> cache_;
  nlohmann::json rows_ = nlohmann::json::array();
  std::unique_ptr<PictureRenderer> pictures_;
};

/// One experiment of `clothbench reproduce`.
struct Experiment {
  std::string id;
  std::string title;
  std::function<void(ExperimentContext&)> run;
  /// The scene runs its tables list, in their order, without running them (what `run` asks run() for); empty
  /// where the experiment does not list them ahead.
  std::function<std::vector<ExperimentContext::Request>(const ExperimentContext&)> runs = {};
};

/// Every experiment, in the order `reproduce` runs them.
const std::vector<Experiment>& experiments();

}  // namespace clothbench

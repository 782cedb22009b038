// ExperimentContext: cached runs, markdown and JSON writers, charts through matplotlib.
#include "clothbench/experiments/experiment.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include "clothbench/bench/registry.hpp"
#include "clothbench/bench/report.hpp"
#include "clothbench/bench/run_result_json.hpp"
#include "clothbench/bench/sweep.hpp"
#include "clothbench/config.h"
#include "clothbench/experiments/history.hpp"
#include "clothbench/io/errors.hpp"
#include "experiment_list.hpp"

namespace clothbench {

ExperimentContext::ExperimentContext(std::string out_dir, bool quick, int repetitions, int jobs)
    : out_dir_(std::move(out_dir)), quick_(quick), repetitions_(std::max(1, repetitions)), jobs_(std::max(1, jobs)) {}

namespace {

std::string cache_key(const std::string& scene, const std::string& collider, const std::vector<std::string>& sets) {
  std::string key = scene + "|" + collider;
  for (const auto& s : sets) key += "|" + s;
  return key;
}

Scene scene_for(const std::string& scene, const std::string& collider, const std::vector<std::string>& sets) {
  Scene loaded = load_scene(std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/" + scene, sets);
  loaded.collider = collider;
  return loaded;
}

}  // namespace

bool ExperimentContext::needs_opengl(const std::string& collider) {
  // a forked worker inherits this process's OSMesa state but not llvmpipe's rendering threads: once this process
  // has drawn (a picture, an is-gl map), OpenGL in the child waits forever for threads that are not there
  const std::optional<ColliderInfo> c = collider_info(collider);
  return c && c->needs != Needs::kNothing;
}

void ExperimentContext::prefetch(const std::vector<Request>& requests) {
  if (jobs_ <= 1) return;
  std::vector<Request> todo;
  for (const Request& q : requests)
    if (!cache_.count(cache_key(q.scene, q.collider, q.sets)) && !needs_opengl(q.collider)) todo.push_back(q);
  if (todo.empty()) return;
  const std::string dir = folder(".prefetch");
  const auto file = [&](std::size_t k) { return dir + "/" + std::to_string(k) + ".json"; };
  std::cerr << "  prefetching " << todo.size() << " runs in " << jobs_ << " worker processes\n";
  std::size_t done = 0;
  run_children(
      todo.size(), jobs_,
      [&](std::size_t k) {
        try {
          const Scene s = scene_for(todo[k].scene, todo[k].collider, todo[k].sets);
          nlohmann::json runs = nlohmann::json::array();
          RunOptions o = todo[k].options;
          o.progress = false;
          for (int r = 0; r < repetitions_; ++r) runs.push_back(to_json(run_scene(s, o), true));
          write_text_file(file(k), runs.dump());
          return 0;
        } catch (const std::exception&) {
          return 2;  // run() meets the error again and reports it
        }
      },
      [&](std::size_t k, int) {
        std::ifstream in(file(k));
        const auto runs = nlohmann::json::parse(in, nullptr, false);
        if (runs.is_array()) {
          std::vector<RunResult> results;
          for (const auto& j : runs) results.push_back(run_result_from_json(j));
          cache_.emplace(cache_key(todo[k].scene, todo[k].collider, todo[k].sets), std::move(results));
        }
        std::filesystem::remove(file(k));
        std::cerr << "  prefetched " << ++done << " of " << todo.size() << "\n";
      });
  std::filesystem::remove(dir);
}

std::string ExperimentContext::grid_note(std::size_t runs) const {
  const std::string how = jobs_ > 1 ? "in " + std::to_string(jobs_) + " worker processes at once (`reproduce --jobs " +
                                          std::to_string(jobs_) +
                                          "`, each run on one thread; on a machine with fewer "
                                          "free cores than workers their times are inflated alike)"
                                    : "one after another in one process (`reproduce --jobs 1`)";
  return "This grid (" + std::to_string(runs) + " runs) ran " + how +
         "; a wider one runs with `clothbench sweep SCENE --collider a,b --set key=v1,v2 --jobs N`, or on a Slurm "
         "cluster with `--slurm` (docs/cli.md, \"Sweeps beyond one machine\").";
}

const RunResult& ExperimentContext::run(const std::string& scene, const std::string& collider,
                                        const std::vector<std::string>& sets, const RunOptions& options, int at_least) {
  const std::string key = cache_key(scene, collider, sets);
  const int n = std::max(repetitions_, at_least);
  const auto it = cache_.find(key);
  const int have = it == cache_.end() ? 0 : int(it->second.size());
  if (have < n) {
    // cached only once every run has succeeded: a run that throws leaves the request as it was
    const Scene with = scene_for(scene, collider, sets);
    std::vector<RunResult> more;
    for (int r = have; r < n; ++r) {
      RunOptions o = options;
      if (o.label.empty()) o.label = with.name + "/" + collider;
      std::cerr << "  running " << o.label << (n > 1 ? " #" + std::to_string(r + 1) : "") << "\n";
      more.push_back(run_scene(with, o));
    }
    auto& runs = cache_[key];
    std::move(more.begin(), more.end(), std::back_inserter(runs));
  }
  return median_run(cache_.at(key));
}

std::vector<const RunResult*> ExperimentContext::repetitions_of(const RunResult& r) const {
  for (const auto& [key, runs] : cache_)
    for (const RunResult& rep : runs)
      if (&rep == &r) {
        std::vector<const RunResult*> all;
        for (const RunResult& each : runs) all.push_back(&each);
        return all;
      }
  return {&r};  // not one of run()'s
}

void ExperimentContext::add_run(const RunResult& r, const std::string& name, const nlohmann::json& extra) {
  std::vector<nlohmann::json> rows;
  for (const RunResult* each : repetitions_of(r)) rows.push_back(result_row(*each, name));
  for (auto& row : rows) row.update(extra);
  for (auto& row : repetition_rows(rows)) rows_.push_back(std::move(row));
}

std::vector<std::string> ExperimentContext::colliders(const std::vector<std::string>& wanted) const {
  const auto built = available_colliders();
  std::vector<std::string> out;
  for (const auto& w : wanted) {
    if (std::find(built.begin(), built.end(), w) != built.end()) {
      out.push_back(w);
    } else {
      std::cerr << "  note: collider " << w << " is not built; its rows are left out\n";
    }
  }
  return out;
}

std::vector<std::string> ExperimentContext::colliders(const ColliderFilter& keep) const {
  for (const ColliderInfo& c : all_colliders())
    if (!c.built && keep(c)) std::cerr << "  note: collider " << c.name << " is not built; its rows are left out\n";
  return clothbench::colliders(keep);
}

std::vector<std::string> lead_first(const std::string& lead, std::vector<std::string> names) {
  const auto it = std::find(names.begin(), names.end(), lead);
  if (it != names.end()) std::rotate(names.begin(), it, it + 1);
  return names;
}

PictureRenderer& ExperimentContext::pictures() {
  if (!pictures_) pictures_ = make_picture_renderer();
  return *pictures_;
}

std::string ExperimentContext::path(const std::string& relative) const {
  const std::filesystem::path p = std::filesystem::path(out_dir_) / relative;
  std::error_code ec;
  std::filesystem::create_directories(p.parent_path(), ec);
  if (ec) throw InputError(p.parent_path().string() + ": cannot create the output folder: " + ec.message());
  return p.string();
}

std::string ExperimentContext::folder(const std::string& relative) const {
  const std::filesystem::path p = std::filesystem::path(out_dir_) / relative;
  std::error_code ec;
  std::filesystem::create_directories(p, ec);
  if (ec) throw InputError(p.string() + ": cannot create the output folder: " + ec.message());
  return p.lexically_normal().string();
}

std::string markdown_summary(const std::vector<std::string>& lines) {
  if (lines.size() > 5)
    throw std::logic_error("a page's summary has at most five lines, not " + std::to_string(lines.size()));
  if (lines.empty()) return "";
  std::string md = "**Summary.**\n\n";
  for (const auto& line : lines) md += "- " + line + "\n";
  return md + "\n";
}

void ExperimentContext::write(const std::string& id, const std::string& title, const std::string& body,
                              const std::vector<std::string>& summary) {
  const nlohmann::json context = machine_context();
  std::ostringstream md;
  md << "# " << id << ": " << title << "\n\n"
     << markdown_summary(summary) << "Generated by `clothbench reproduce --only " << id << (quick_ ? " --quick" : "")
     << "`; never edited by hand.\n"
     << "Machine: " << context["cpu_model"].get<std::string>() << ", " << context["num_cpus"] << " cores; "
     << context["compiler"].get<std::string>() << " " << context["build_type"].get<std::string>() << " ("
     << context["cxx_flags"].get<std::string>() << "); git " << context["git_sha"].get<std::string>() << "; "
     << context["date"].get<std::string>() << ".\n\n"
     << "Definitions: " << kDefinitions << ".\n\n"
     << body;
  write_text_file(path(id + ".md"), md.str());
  write_text_file(path(id + ".json"), result_document(rows_).dump(2) + "\n");
  if (!rows_.empty()) append_history(path("history.jsonl"), history_entry(id, rows_, context, quick_));
  rows_ = nlohmann::json::array();
}

bool ExperimentContext::chart(const std::string& name, nlohmann::json spec) {
  const std::string png = path(name + ".png");
  spec["out"] = png;
  const std::string spec_path = png + ".spec.json";
  write_text_file(spec_path, spec.dump());
  const int rc = run_python_script("experiments/plot/plot.py", "'" + spec_path + "'");
  std::error_code ec;
  std::filesystem::remove(spec_path, ec);
  if (rc != 0) {
    std::cerr << "  warning: chart " << png
              << " not drawn (python3 with matplotlib is needed: apt-get install python3-matplotlib)\n";
    return false;
  }
  return true;
}

const std::vector<Experiment>& experiments() {
  static const std::vector<Experiment> all = [] {
    std::vector<Experiment> e;
    add_dressing_t1_experiments(e);
    add_walking_t1_experiments(e);
    add_dressing_t2_experiments(e);
    add_dressing_f8_experiments(e);
    add_walking_t2_experiments(e);
    add_walking_f8_experiments(e);
    add_durupinar_f6_experiments(e);
    add_made_to_measure_experiments(e);
    add_cloth_cloth_experiments(e);
    add_integrators_experiments(e);
    add_limiters_experiments(e);
    add_stability_experiments(e);
    add_colliders_experiments(e);
    add_pareto_minimal_experiments(e);
    add_deviations_experiments(e);
    add_pictures_experiments(e);
    add_claims_experiments(e);
    return e;
  }();
  return all;
}

}  // namespace clothbench

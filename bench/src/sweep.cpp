// Sweep grids, shards, point files and merging (sweep.hpp).
#include "clothbench/bench/sweep.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <filesystem>
#include <set>

#include "clothbench/bench/report.hpp"
#include "clothbench/bench/runner.hpp"
#include "clothbench/bench/scene.hpp"
#include "clothbench/io/errors.hpp"

namespace clothbench {

namespace fs = std::filesystem;

SweepAxis parse_axis(const std::string& arg) {
  const auto eq = arg.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set " + arg + ": expected section.key=value[,value...]");
  SweepAxis a{arg.substr(0, eq), {}};
  // split the values on commas outside brackets and quotes (an array value keeps its commas)
  std::string cur;
  int depth = 0;
  bool quoted = false;
  for (char c : arg.substr(eq + 1)) {
    if (c == '"') quoted = !quoted;
    if (!quoted && (c == '[' || c == '{')) ++depth;
    if (!quoted && (c == ']' || c == '}')) --depth;
    if (c == ',' && depth == 0 && !quoted) {
      a.values.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  a.values.push_back(cur);
  for (const auto& v : a.values)
    if (v.empty()) throw InputError("--set " + arg + ": an empty value (two commas, or one at an end)");
  return a;
}

nlohmann::json SweepGrid::to_json() const {
  nlohmann::json ax = nlohmann::json::array();
  for (const auto& a : axes) ax.push_back({{"key", a.key}, {"values", a.values}});
  return {{"scene", scene}, {"colliders", colliders}, {"axes", ax}, {"repetitions", repetitions}, {"end_state", end_state}};
}

SweepGrid SweepGrid::from_json(const nlohmann::json& j) {
  SweepGrid g;
  g.scene = j.at("scene").get<std::string>();
  g.colliders = j.at("colliders").get<std::vector<std::string>>();
  for (const auto& a : j.at("axes")) g.axes.push_back({a.at("key"), a.at("values").get<std::vector<std::string>>()});
  g.repetitions = j.at("repetitions").get<int>();
  g.end_state = j.value("end_state", false);
  return g;
}

std::vector<SweepPoint> expand_grid(const SweepGrid& grid) {
  std::vector<SweepPoint> points;
  const std::vector<std::string> colliders = grid.colliders.empty() ? std::vector<std::string>{""} : grid.colliders;
  for (const std::string& c : colliders) {
    // the axes as an odometer: the last one turns fastest
    std::vector<std::size_t> at(grid.axes.size(), 0);
    for (bool more = true; more;) {
      SweepPoint p{static_cast<int>(points.size()), c, {}, c.empty() ? "scene's collider" : c};
      for (std::size_t k = 0; k < grid.axes.size(); ++k) {
        p.sets.push_back(grid.axes[k].key + "=" + grid.axes[k].values[at[k]]);
        p.name += "/" + p.sets.back();
      }
      points.push_back(p);
      more = false;
      for (std::size_t k = grid.axes.size(); k-- > 0;) {
        if (++at[k] < grid.axes[k].values.size()) {
          more = true;
          break;
        }
        at[k] = 0;
      }
    }
  }
  return points;
}

std::pair<int, int> parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  try {
    if (slash != std::string::npos) {
      std::size_t used_i = 0, used_n = 0;
      const int i = std::stoi(text.substr(0, slash), &used_i), n = std::stoi(text.substr(slash + 1), &used_n);
      if (used_i == slash && used_n == text.size() - slash - 1 && n > 0 && i >= 0 && i < n) return {i, n};
    }
  } catch (const std::exception&) {
  }
  throw InputError("--shard " + text + ": expected i/N with 0 <= i < N (e.g. 0/4)");
}

std::vector<SweepPoint> shard_points(const std::vector<SweepPoint>& all, int i, int n) {
  std::vector<SweepPoint> out;
  for (std::size_t k = static_cast<std::size_t>(i); k < all.size(); k += static_cast<std::size_t>(n)) out.push_back(all[k]);
  return out;
}

void run_children(std::size_t count, int jobs, const std::function<int(std::size_t)>& child,
                  const std::function<void(std::size_t, int)>& done) {
  std::map<pid_t, std::size_t> running;
  std::size_t next = 0;
  while (next < count || !running.empty()) {
    while (next < count && static_cast<int>(running.size()) < std::max(1, jobs)) {
      std::fflush(nullptr);
      const pid_t pid = fork();
      if (pid < 0) throw std::runtime_error("fork failed: no more worker processes");
      if (pid == 0) _exit(child(next));
      running.emplace(pid, next++);
    }
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    const std::size_t k = it->second;
    running.erase(it);
    done(k, status);
  }
}

std::string point_path(const std::string& dir, const SweepPoint& p) {
  return (fs::path(dir) / "points" / (std::to_string(p.index) + ".json")).string();
}

std::string point_error_path(const std::string& dir, const SweepPoint& p) {
  return (fs::path(dir) / "points" / (std::to_string(p.index) + ".error.json")).string();
}

namespace {

nlohmann::json point_json(const SweepPoint& p) {
  return {{"index", p.index}, {"name", p.name}, {"collider", p.collider}, {"sets", p.sets}};
}

}  // namespace

bool point_done(const std::string& dir, const SweepPoint& p) {
  const std::string path = point_path(dir, p);
  if (!fs::exists(path)) return false;
  const nlohmann::json j = read_json_file(path);
  if (!j.contains("point") || j["point"].value("name", "") != p.name)
    throw InputError(path + ": the result of another point (" + (j.contains("point") ? j["point"].value("name", "?") : "?") +
                     ") where this grid has " + p.name + ": use another --out folder");
  return true;
}

void run_point(const SweepGrid& grid, const SweepPoint& p, const std::string& dir) {
  Scene scene = load_scene(grid.scene, p.sets);
  if (!p.collider.empty()) scene.collider = p.collider;
  RunOptions options;
  options.progress = false;
  std::vector<RunResult> runs;
  for (int r = 0; r < grid.repetitions; ++r) runs.push_back(run_scene(scene, options));
  nlohmann::json doc = runs_document(runs, scene.name + "/" + p.name, grid.scene, grid.end_state);
  doc["point"] = point_json(p);
  fs::remove(point_error_path(dir, p));
  write_text_file(point_path(dir, p), doc.dump(1) + "\n");
}

void write_point_error(const std::string& dir, const SweepPoint& p, const std::string& error, int exit_status) {
  nlohmann::json j = point_json(p);
  j["error"] = error;
  j["exit_status"] = exit_status;
  write_text_file(point_error_path(dir, p), j.dump(1) + "\n");
}

void claim_folder(const std::string& dir, const SweepGrid& grid) {
  const std::string path = (fs::path(dir) / "sweep.json").string();
  if (fs::exists(path)) {
    const nlohmann::json there = read_json_file(path);
    if (there != grid.to_json())
      throw InputError(dir + " holds another sweep (" + path + " differs from this grid): use another --out folder");
    return;
  }
  fs::create_directories(fs::path(dir) / "points");
  write_text_file(path, grid.to_json().dump(1) + "\n");
}

namespace {

// the build a result came from: results of different builds are not comparable
std::string build_of(const nlohmann::json& context) {
  std::string b;
  for (const char* k : {"git_sha", "compiler", "cxx_flags", "build_type"}) b += context.value(k, std::string("?")) + "|";
  return b;
}

// one folder's rows into `out`, its failed and missing points into `failed`; `from` is the folder each row name
// came from: two folders with a row of one name would give rows nobody can tell apart (compare and report match
// rows by name)
void merge_folder(const std::string& dir, nlohmann::json& out, nlohmann::json& failed, std::set<std::string>& builds,
                  nlohmann::json& context, std::map<std::string, std::string>& from) {
  const SweepGrid grid = SweepGrid::from_json(read_json_file((fs::path(dir) / "sweep.json").string()));
  for (const SweepPoint& p : expand_grid(grid)) {
    if (fs::exists(point_path(dir, p)) && point_done(dir, p)) {
      const nlohmann::json doc = read_json_file(point_path(dir, p));
      builds.insert(build_of(doc["context"]));
      if (context.is_null()) context = doc["context"];
      for (const auto& row : doc["benchmarks"]) {
        const std::string name = row.value("name", "");
        const auto [it, first] = from.emplace(name, dir);
        if (!first && it->second != dir)
          throw InputError("merge: " + dir + " and " + it->second + " both hold the point '" + name +
                           "': rows of one name cannot be told apart (merge the two sweeps separately, or run "
                           "one of them from a scene of another name)");
        out.push_back(row);
      }
    } else if (fs::exists(point_error_path(dir, p))) {
      nlohmann::json e = read_json_file(point_error_path(dir, p));
      e["folder"] = dir;
      failed.push_back(e);
    } else {
      nlohmann::json e = point_json(p);
      e["folder"] = dir;
      e["error"] = "missing: the point never ran (or is still running)";
      failed.push_back(e);
    }
  }
}

}  // namespace

nlohmann::json merge_sweeps(const std::vector<std::string>& dirs, bool allow_mixed) {
  nlohmann::json rows = nlohmann::json::array(), failed = nlohmann::json::array(), context;
  std::set<std::string> builds;
  nlohmann::json grids = nlohmann::json::array();
  std::map<std::string, std::string> from;
  std::set<std::string> seen;
  for (const std::string& dir : dirs) {
    if (!fs::exists(fs::path(dir) / "sweep.json")) throw InputError(dir + ": not a sweep folder (no sweep.json)");
    if (!seen.insert(fs::weakly_canonical(dir).string()).second)
      throw InputError("merge: " + dir + " is named twice (its rows would count twice)");
    merge_folder(dir, rows, failed, builds, context, from);
    grids.push_back(read_json_file((fs::path(dir) / "sweep.json").string()));
  }
  if (builds.size() > 1 && !allow_mixed) {
    std::string list;
    for (const auto& b : builds) list += "\n  " + b;
    throw InputError("merge: the points come from " + std::to_string(builds.size()) +
                     " builds (git SHA|compiler|flags|build type):" + list + "\n(--allow-mixed joins them anyway)");
  }
  nlohmann::json doc{{"context", context.is_null() ? nlohmann::json::object() : context}, {"benchmarks", rows}};
  doc["context"]["sweeps"] = grids;
  doc["context"]["mixed_builds"] = builds.size() > 1;
  doc["failed"] = failed;
  return doc;
}

}  // namespace clothbench

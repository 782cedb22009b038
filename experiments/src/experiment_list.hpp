#pragma once
// The experiments of `clothbench reproduce`, one file each (named after its IDs), each adding its own.
#include <vector>

#include "clothbench/experiments/experiment.hpp"

namespace clothbench {

void add_dressing_t1_experiments(std::vector<Experiment>& out);
void add_walking_t1_experiments(std::vector<Experiment>& out);
void add_dressing_t2_experiments(std::vector<Experiment>& out);
void add_dressing_f8_experiments(std::vector<Experiment>& out);
void add_walking_t2_experiments(std::vector<Experiment>& out);
void add_walking_f8_experiments(std::vector<Experiment>& out);
void add_durupinar_f6_experiments(std::vector<Experiment>& out);
void add_made_to_measure_experiments(std::vector<Experiment>& out);
void add_cloth_cloth_experiments(std::vector<Experiment>& out);
void add_integrators_experiments(std::vector<Experiment>& out);
void add_limiters_experiments(std::vector<Experiment>& out);
void add_stability_experiments(std::vector<Experiment>& out);
void add_colliders_experiments(std::vector<Experiment>& out);
void add_pareto_minimal_experiments(std::vector<Experiment>& out);
void add_deviations_experiments(std::vector<Experiment>& out);
void add_pictures_experiments(std::vector<Experiment>& out);
void add_claims_experiments(std::vector<Experiment>& out);

}  // namespace clothbench

// Parameter sweeps: a plan of runs, each a set of scene overrides (--set), as a grid
// or zipped lists of values, or as a reproducible Monte Carlo sample; the commands that run
// them (a worker pool, GNU Parallel, a Slurm array); and sweep.csv built from whatever run
// folders exist, so an in-process sweep and a cluster run end in the same files.
//
// Folder layout: DIR/plan.csv (id and values of every run), DIR/runs/<id>/ (one `plastica run
// --curves-only` each: curve.csv, run.json), DIR/logs/<id>.txt, DIR/sweep.csv; with --emit jobs
// also DIR/jobs.txt (one command per line) and DIR/sweep.sbatch.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace plastica {

// What a sweep may hold: runs of a grid or a sample, and keys varied (each key a chart).
inline constexpr std::size_t max_sweep_runs = 1'000'000;
inline constexpr std::size_t max_sweep_keys = 64;

struct SweepPlan {
    std::vector<std::string> keys;                  // scene key paths, as --set takes them
    std::vector<std::string> ids;                   // r0001, r0002, …
    std::vector<std::vector<std::string>> values;   // per run, one value per key
};

// --vary KEY=v1,v2,…: the grid of all combinations (the first key varies slowest), or with
// `zip` the lists side by side (all the same length).
SweepPlan grid_plan(const std::vector<std::pair<std::string, std::vector<std::string>>>& lists, bool zip);

// --sample KEY=normal:μ:σ | lognormal:μ:σ (of the logarithm) | uniform:a:b, N runs from a seed:
// the same seed gives the same values.
struct SampledKey {
    std::string key, law;
    double a = 0.0, b = 0.0;
};
SampledKey parse_sample(const std::string& text); // throws StudyError naming the text
SweepPlan sample_plan(const std::vector<SampledKey>& keys, int runs, std::uint64_t seed);

// The values of key k that a sweep's check reads the scene with before it starts: every distinct
// one of a grid, the smallest and largest of a sample.
std::vector<std::string> values_to_check(const SweepPlan& plan, std::size_t k, bool sampled);

void write_plan(const std::string& dir, const SweepPlan& plan);
SweepPlan read_plan(const std::string& dir); // throws StudyError when there is none

// What each run writes: curve.csv and run.json (the default), also its VTU series, or also
// its pictures.
enum class RunOutput { curves, series, pictures };
RunOutput parse_run_output(const std::string& text); // throws StudyError naming the text

// The argument list of one run: run SCENE --set KEY=VALUE… --curves-only -q -o DIR/runs/<id>
// (--no-render for a series, neither for pictures).
std::vector<std::string> run_arguments(const std::string& scene, const std::string& dir, const SweepPlan& plan, std::size_t run,
                                       RunOutput output = RunOutput::curves);
// Whether a run folder holds a finished run (run.json with a final status).
bool run_finished(const std::string& dir, const std::string& id);

// One word for a POSIX shell, whatever it holds: in single quotes, each ' written '\''.
std::string quoted_for_shell(const std::string& s);
// jobs.txt (one shell-quoted command line per run) and sweep.sbatch (a Slurm array over it).
void write_jobs(const std::string& dir, const std::string& program, const std::string& scene, const SweepPlan& plan,
                RunOutput output = RunOutput::curves);

struct SweepSummary {
    int runs = 0, completed = 0, stopped = 0, failed = 0, missing = 0;
    std::vector<std::string> missing_ids, failed_ids;
};
// sweep.csv: per run the values, status and reason, peak load and its displacement, the load
// at the given displacements, iterations, steps and seconds; missing runs listed as such.
SweepSummary write_sweep_csv(const std::string& dir, const std::vector<double>& at);

// What the charts of a sweep need: per run its values, whether it gave a result, its peak load
// and its load–displacement curve.
struct SweepRunResult {
    std::string id;
    std::vector<std::string> values;
    bool finished = false;
    std::string scene_file; // as run.json records it
    double peak_load = 0.0;
    std::vector<double> displacement, load;
};
std::vector<SweepRunResult> read_sweep_results(const std::string& dir, const SweepPlan& plan);

} // namespace plastica

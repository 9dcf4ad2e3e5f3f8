// Observer that writes every k-th converged step as out/<scene>/vtu/step_NNNNNN.vtu (appended
// raw data, uncompressed or in LZ4 or zlib blocks: vtk_xml_format.hpp), and keeps <scene>.pvd valid after each step in
// O(1): the new entries are written over the closing tags, which follow them again (the file
// is never rewritten whole, whatever the step count). The PVD time is monotone (the
// step index, or the cumulative arc length); the load factor is field data. The base line and
// spring anchors go once to base.vtp, listed as part 1 of every time step.
// Arrays are those of the result schema (result_schema.hpp), written only where the scene has
// them.
#pragma once

#include "analysis/step_result.hpp"
#include "model/model.hpp"
#include "step_dataset.hpp"
#include "vtk_xml_format.hpp"

#include <cstdio>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace plastica {

// model: the model time of a transient scene (StepResult::time).
enum class SeriesTime { step, arc_length, model };

struct SeriesOptions {
    int every = 1;                  // write every k-th step (the first and last always)
    SeriesTime time = SeriesTime::step;
    Compression compression = Compression::none;
};

class VtuSeriesWriter {
public:
    VtuSeriesWriter(const Model& model, const std::string& directory, SeriesOptions options = {});
    ~VtuSeriesWriter();
    VtuSeriesWriter(VtuSeriesWriter&&) noexcept;

    void operator()(const StepResult& r);
    // Writes the last step if --every skipped it. Call once when the analysis ends.
    void finish();

    std::size_t steps_written() const { return entries_.size(); }
    const std::string& pvd_path() const { return pvd_path_; }

private:
    void write_step(const StepResult& r);
    void write_base();
    void append_to_pvd(double time, const std::string& file);
    void remove_earlier_steps() noexcept;

    const Model* model_;
    std::string directory_;
    std::string pvd_path_;
    SeriesOptions options_;
    std::vector<std::pair<double, std::string>> entries_; // time, relative file name
    StepDataset dataset_; // the arrays of each step
    std::set<std::string> earlier_steps_; // step files of an earlier run not yet rewritten
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> pvd_{nullptr, &std::fclose};
    long pvd_tail_ = 0; // where the closing tags start
    bool has_base_file_ = false;
    std::optional<StepResult> pending_;                   // last skipped step
    UncompressedGridFile step_file_; // the last step's file, uncompressed: the next overwrites its values
};

std::string step_file_name(int step);

} // namespace plastica

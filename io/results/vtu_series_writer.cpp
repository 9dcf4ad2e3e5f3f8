#include "vtu_series_writer.hpp"

#include "arrays/base_lines.hpp"

#include "atomic_file.hpp"
#include "result_schema.hpp"

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace plastica {

namespace fs = std::filesystem;

std::string step_file_name(int step) {
    char name[32];
    std::snprintf(name, sizeof name, "step_%06d.vtu", step);
    return name;
}

VtuSeriesWriter::VtuSeriesWriter(const Model& model, const std::string& directory, SeriesOptions options)
    : model_(&model), directory_(directory), pvd_path_((fs::path(directory) / (model.name + ".pvd")).string()),
      options_(options), dataset_(model) {
    if (options_.every < 1) options_.every = 1;
    fs::create_directories(fs::path(directory) / "vtu");
    // An earlier run's step files: rewritten in place where this run has the same steps, the
    // others removed at the end (finish).
    for (const auto& entry : fs::directory_iterator(fs::path(directory) / "vtu"))
        if (entry.path().extension() == ".vtu") earlier_steps_.insert(entry.path().filename().string());
    write_base();
}

VtuSeriesWriter::~VtuSeriesWriter() { remove_earlier_steps(); }
VtuSeriesWriter::VtuSeriesWriter(VtuSeriesWriter&&) noexcept = default;

void VtuSeriesWriter::operator()(const StepResult& r) {
    if (r.step == 0 || r.step % options_.every == 0) {
        write_step(r);
        pending_.reset();
    } else {
        pending_ = r;
    }
}

void VtuSeriesWriter::finish() {
    try {
        if (pending_) write_step(*pending_);
    } catch (...) {
        remove_earlier_steps();
        throw;
    }
    pending_.reset();
    remove_earlier_steps();
}

void VtuSeriesWriter::remove_earlier_steps() noexcept {
    std::error_code ec;
    for (const std::string& name : earlier_steps_) fs::remove(fs::path(directory_) / "vtu" / name, ec);
    earlier_steps_.clear();
}

namespace {
double smallest_time_step(const Model& m) {
    double dt = m.analysis.scheme == Scheme::transient ? m.analysis.transient.time_step : 0.0;
    for (const StageSpec& s : m.stages)
        if (s.scheme == Scheme::transient && (dt == 0.0 || s.transient.time_step < dt)) dt = s.transient.time_step;
    return dt > 0.0 ? dt : 1.0;
}
} // namespace

void VtuSeriesWriter::write_step(const StepResult& r) {
    double time = options_.time == SeriesTime::step ? static_cast<double>(r.step)
                : options_.time == SeriesTime::model ? r.time : r.arc_length;
    // Static steps of a scene in time (gravity before the shaking) happen at one instant; the
    // series needs increasing times, so each sits a millionth of a time step after the one before
    // (the VTU's own `time` says when it is).
    if (options_.time == SeriesTime::model && !entries_.empty() && time <= entries_.back().first)
        time = entries_.back().first + 1e-6 * smallest_time_step(*model_);
    const XmlDataset grid = dataset_(r, time);
    const std::string step_name = step_file_name(r.step), file = "vtu/" + step_name;
    const std::string path = (fs::path(directory_) / file).string();
    // Listed in the PVD only once complete, so no reader of the series sees it half-written.
    if (options_.compression == Compression::none)
        write_file_in_place(path, write_unstructured_grid(grid, step_file_));
    else
        write_file_in_place(path, unstructured_grid_xml(grid, options_.compression));
    earlier_steps_.erase(step_name);
    try {
        append_to_pvd(time, file);
    } catch (...) {
        fs::remove(path); // not listed, so not kept: the series ends at the step before
        throw;
    }
    entries_.emplace_back(time, file);
}

void VtuSeriesWriter::write_base() {
    const Model& m = *model_;
    if (m.springs.empty()) return;
    const XmlDataset poly = base_lines_dataset(m, dataset_.arrays());
    write_file_atomically((fs::path(directory_) / "base.vtp").string(), poly_data_xml(poly, options_.compression));
    has_base_file_ = true;
}

void VtuSeriesWriter::append_to_pvd(double time, const std::string& file) {
    static const std::string closing = "  </Collection>\n</VTKFile>\n";
    if (!pvd_) {
        // Created whole through a temporary file and a rename, then kept open (the stream only
        // holds the descriptor: entries go in with one positioned write each, no read-back).
        write_file_atomically(pvd_path_, "<?xml version=\"1.0\"?>\n"
                                         "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
                                         "  <Collection>\n" + closing);
        pvd_.reset(std::fopen(pvd_path_.c_str(), "r+b"));
        if (!pvd_) throw std::runtime_error("cannot open " + pvd_path_);
        pvd_tail_ = static_cast<long>(std::filesystem::file_size(pvd_path_) - closing.size());
    }
    // The time as a stream with precision(17) prints it (%.17g): it reads back to the bit.
    char digits[32];
    const std::string timestep(digits, std::to_chars(digits, digits + sizeof digits, time, std::chars_format::general, 17).ptr);
    std::string entry = "    <DataSet timestep=\"" + timestep + "\" group=\"\" part=\"0\" file=\"" + file + "\"/>\n";
    if (has_base_file_) entry += "    <DataSet timestep=\"" + timestep + "\" group=\"\" part=\"1\" file=\"base.vtp\"/>\n";
    // One write of the new entries and the closing tags over the old closing tags: the file
    // is a complete collection before and after it.
    const int fd = ::fileno(pvd_.get());
    try {
        write_all_at(fd, entry + closing, pvd_tail_, pvd_path_);
    } catch (...) {
        // A full disk: put the closing tags back where they were (those bytes are the file's
        // already) and cut off whatever part of the entry went out; the error says what happened.
        try {
            write_all_at(fd, closing, pvd_tail_, pvd_path_);
        } catch (...) {
        }
        if (::ftruncate(fd, pvd_tail_ + static_cast<long>(closing.size())) != 0) {
            // nothing more to be done
        }
        throw;
    }
    pvd_tail_ += static_cast<long>(entry.size());
}

} // namespace plastica

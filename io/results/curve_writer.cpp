#include "curve_writer.hpp"

#include "analysis/support_reactions.hpp"
#include "atomic_file.hpp"
#include "result_schema.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <charconv>
#include <cstring>
#include <stdexcept>

namespace plastica {

CurveWriter::CurveWriter(const std::string& path, const Model& model) : path_(path), model_(&model) {
    fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd_ < 0) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
    const std::string header = curve_header(model);
    try {
        write_all(fd_, header.data(), header.size(), path_);
    } catch (...) {
        ::close(fd_);
        throw;
    }
    size_ = before_last_row_ = static_cast<long long>(header.size());
}

CurveWriter::~CurveWriter() {
    if (fd_ >= 0) ::close(fd_);
}

namespace {
// A row of numbers as a stream with precision(12) prints them (%.12g), without the stream's
// locale machinery: the row costs a tenth.
class Row {
public:
    Row& operator<<(double v) { return put([v](char* first, char* last) { return std::to_chars(first, last, v, std::chars_format::general, 12); }); }
    Row& operator<<(int v) { return put([v](char* first, char* last) { return std::to_chars(first, last, v); }); }
    Row& operator<<(char c) {
        text_.push_back(c);
        return *this;
    }
    Row& operator<<(const char* s) {
        text_ += s;
        return *this;
    }
    const std::string& text() const { return text_; }

private:
    static constexpr std::size_t widest = 32; // "-1.23456789012e-308" and any int fit
    template <class Format>
    Row& put(Format format) {
        const std::size_t used = text_.size();
        text_.resize(used + widest);
        const std::to_chars_result r = format(text_.data() + used, text_.data() + text_.size());
        text_.resize(static_cast<std::size_t>(r.ptr - text_.data()));
        return *this;
    }
    std::string text_;
};
} // namespace

std::string curve_header(const Model& model) {
    std::string header = "step,load_factor,load,control_displacement,iterations,contact_count,hinge_count,"
                         "plastic_hinge_count,base_reaction,contact_length,negative_pivots,accepted_by,residual";
    // A staged run says which stage each step belongs to, and a run of several patterns each
    // pattern's factor (load_factor is the factor of the pattern the step's stage drives).
    if (!model.stages.empty()) header += ",stage";
    // Self-contact: the pairs of surfaces pressed together and the normal force they exchange.
    if (!model.self_contact.empty()) header += ",surface_contacts,surface_contact_force";
    for (int p : result::active_patterns(model)) header += ",factor_" + model.patterns[static_cast<std::size_t>(p)];
    bool shear = false;
    for (const std::string& name : reaction_columns(model)) {
        header += ',' + name;
        shear = shear || (name.size() > 3 && name.compare(name.size() - 3, 3, "_fx") == 0);
    }
    // A frame's base shear: what the structure pushes its supports with along x (not a half
    // model's, whose x reactions hold its symmetry line).
    if (shear && !model.report.mirror_x) header += ",base_shear";
    // An elastic path: the critical point a step passed, and where it lies (empty elsewhere).
    if (model.tracks_critical_points()) header += ",critical_point,critical_load_factor";
    // Motion in time: the time and the energy accounts (EnergyTerms).
    if (model.transient())
        header += ",time,kinetic_energy,strain_energy,plastic_dissipation,damping_work,contact_work,external_work,"
                  "ground_motion_work,energy_error";
    header += '\n';
    return header;
}

std::string curve_row(const Model& model, const StepResult& r) {
    Row row;
    row << r.step << ',' << r.load_factor << ',' << r.load << ',' << r.control_displacement << ','
        << r.iterations << ',' << r.contact_count << ',' << r.hinge_count << ','
        << r.plastic_hinge_count << ',' << r.base_reaction << ',' << r.contact_length << ','
        << r.negative_pivots << ',' << to_string(r.accepted_by) << ',' << r.residual;
    if (!model.stages.empty()) row << ',' << r.stage;
    if (!model.self_contact.empty()) {
        double total = 0.0;
        for (const SurfaceContactResult& c : r.surface_contacts) total += std::hypot(c.force[0], c.force[1]);
        row << ',' << static_cast<int>(r.surface_contacts.size()) << ',' << total;
    }
    for (int p : result::active_patterns(model))
        row << ',' << (static_cast<std::size_t>(p) < r.pattern_factors.size() ? r.pattern_factors[static_cast<std::size_t>(p)] : 0.0);
    double base_shear = 0.0;
    bool shear = false; // as in curve_header
    for (const SupportReaction& s : support_reactions(model, r))
        for (int d = 0; d < dofs_per_node; ++d)
            if (s.reported[d]) {
                row << ',' << s.force[d];
                if (d == 0) base_shear -= s.force[d], shear = true;
            }
    if (shear && !model.report.mirror_x) row << ',' << base_shear + 0.0;
    if (model.tracks_critical_points()) {
        if (r.critical) row << ',' << to_string(r.critical->kind) << ',' << r.critical->load_factor;
        else row << ",,";
    }
    if (model.transient()) {
        const EnergyTerms& e = r.energy;
        row << ',' << r.time << ',' << e.kinetic << ',' << e.strain << ',' << e.plastic << ',' << e.damping << ',' << e.contact
            << ',' << e.external << ',' << e.ground << ',' << e.error;
    }
    row << '\n';
    return row.text();
}

void CurveWriter::operator()(const StepResult& r) {
    const std::string text = curve_row(*model_, r);
    try {
        write_all(fd_, text.data(), text.size(), path_);
    } catch (...) {
        truncate_to(size_); // a part of the row may have gone out
        throw;
    }
    before_last_row_ = size_;
    size_ += static_cast<long long>(text.size());
}

void CurveWriter::take_back_last_row() {
    truncate_to(before_last_row_);
    size_ = before_last_row_;
}

void CurveWriter::truncate_to(long long size) {
    // Shrinking needs no new blocks, so it works on a full disk too.
    if (::ftruncate(fd_, static_cast<off_t>(size)) != 0)
        throw std::runtime_error("cannot shorten " + path_ + ": " + std::strerror(errno));
}

} // namespace plastica

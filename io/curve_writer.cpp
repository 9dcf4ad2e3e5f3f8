#include "curve_writer.hpp"

#include "analysis/support_reactions.hpp"
#include "atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <sstream>
#include <stdexcept>

namespace plastica {

CurveWriter::CurveWriter(const std::string& path, const Model& model) : path_(path), model_(&model) {
    fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC, 0644);
    if (fd_ < 0) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
    std::string header = "step,load_factor,load,control_displacement,iterations,contact_count,hinge_count,"
                         "plastic_hinge_count,base_reaction,contact_length,negative_pivots,accepted_by,residual";
    for (const std::string& name : reaction_columns(model)) header += ',' + name;
    header += '\n';
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

void CurveWriter::operator()(const StepResult& r) {
    std::ostringstream row;
    row.precision(12);
    row << r.step << ',' << r.load_factor << ',' << r.load << ',' << r.control_displacement << ','
        << r.iterations << ',' << r.contact_count << ',' << r.hinge_count << ','
        << r.plastic_hinge_count << ',' << r.base_reaction << ',' << r.contact_length << ','
        << r.negative_pivots << ',' << to_string(r.accepted_by) << ',' << r.residual;
    for (const SupportReaction& s : support_reactions(*model_, r))
        for (int d = 0; d < dofs_per_node; ++d)
            if (s.reported[d]) row << ',' << s.force[d];
    row << '\n';
    const std::string text = row.str();
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

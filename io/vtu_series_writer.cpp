#include "vtu_series_writer.hpp"
#include "raw_vtu_format.hpp"

#include "atomic_file.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace plastica {

namespace fs = std::filesystem;

std::string step_file_name(int step) {
    char name[32];
    std::snprintf(name, sizeof name, "step_%06d.vtu", step);
    return name;
}

namespace {

bool has_bilateral(const Model& m) {
    return std::any_of(m.springs.begin(), m.springs.end(), [](const FoundationSpring& s) { return !s.unilateral; });
}

// force·length, force/length: the compound units of moments and pressures.
std::string compound(const std::string& a, const char* op, const std::string& b) {
    if (a.empty() || b.empty()) return {};
    return a + op + b;
}

vtkSmartPointer<vtkDoubleArray> make_array(const char* name, int components, vtkIdType tuples) {
    auto a = vtkSmartPointer<vtkDoubleArray>::New();
    a->SetName(name);
    a->SetNumberOfComponents(components);
    a->SetNumberOfTuples(tuples);
    std::fill_n(a->GetPointer(0), tuples * components, 0.0); // vtkDataArray::Fill starts threads
    return a;
}

void add_field(vtkFieldData* fd, const char* name, double value) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfTuples(1);
    a->SetValue(0, value);
    fd->AddArray(a);
}

// VTK's writer makes hundreds of small writes and seeks per file; it writes into memory
// here, and the file goes out in one piece under a temporary name, then is renamed.
template <class Writer>
void write_xml(Writer* writer, const std::string& path, Compression compression = Compression::zlib) {
    writer->WriteToOutputStringOn();
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
    switch (compression) {
    case Compression::none: writer->SetCompressorTypeToNone(); break;
    case Compression::lz4: writer->SetCompressorTypeToLZ4(); break;
    case Compression::zlib: writer->SetCompressorTypeToZLib(); break;
    }
    if (writer->Write() != 1) throw std::runtime_error("VTK could not write " + path);
    write_file_atomically(path, writer->GetOutputString());
}

// The units of the reported load (a force, a moment, a pressure, or none for the load factor)
// and of the control displacement (a length, or radians for a rotation).
std::pair<std::string, std::string> reported_units(const Model& m) {
    const std::string& force = m.report.force_unit;
    const std::string& length = m.report.length_unit;
    std::string load = force;
    if (m.report.measure == ReportSpec::Measure::factor) {
        load.clear();
    } else if (m.uniform_pressure_only()) {
        load = compound(force, "/", length);
    } else if (!m.loads.empty() && std::all_of(m.loads.begin(), m.loads.end(), [](const NodalLoad& l) {
                   return l.value[0] == 0.0 && l.value[1] == 0.0;
               })) {
        load = compound(force, "·", length); // moments only
    }
    return {load, m.analysis.control.dof == 2 ? "rad" : length};
}

} // namespace

struct VtuSeriesWriter::Impl {
    vtkNew<vtkUnstructuredGrid> grid;
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
};

std::vector<std::string> VtuSeriesWriter::point_arrays(const Model& m) {
    std::vector<std::string> names{"displacement", "rotation", "initial_position", "bending_moment"};
    if (!m.supports.empty() || !m.prescribed.empty()) names.push_back("reaction");
    if (!m.supports.empty()) names.push_back("support");
    if (!m.loads.empty() || !m.pressures.empty()) names.push_back("applied_load");
    if (has_bilateral(m)) names.push_back("spring_force");
    if (m.has_unilateral_base()) {
        names.push_back("contact_force");
        names.push_back("gap");
        names.push_back("contact");
    }
    if (m.has_plasticity(Plasticity::hinges)) {
        names.push_back("plastic_utilisation");
        names.push_back("hinge_state");
    }
    return names;
}

std::vector<std::string> VtuSeriesWriter::cell_arrays(const Model& m) {
    std::vector<std::string> names{"axial_force", "moment_i", "moment_j", "shear"};
    if (m.has_plasticity(Plasticity::distributed)) {
        names.push_back("yielded_share");
        names.push_back("section_yielded_share");
        names.push_back("section_curvature");
        names.push_back("section_moment");
    }
    if (m.has_plasticity(Plasticity::hinges)) {
        names.push_back("ei_ratio");
        names.push_back("utilisation_i");
        names.push_back("utilisation_j");
        names.push_back("hinge_state_i");
        names.push_back("hinge_state_j");
    }
    return names;
}

VtuSeriesWriter::VtuSeriesWriter(const Model& model, const std::string& directory, SeriesOptions options)
    : impl_(std::make_unique<Impl>()), model_(&model), directory_(directory),
      pvd_path_((fs::path(directory) / (model.name + ".pvd")).string()), options_(options) {
    if (options_.every < 1) options_.every = 1;
    // The writer computes array ranges with vtkSMPTools; for arrays of a few hundred values a
    // thread pool costs far more than it saves.
    vtkSMPTools::SetBackend("Sequential");
    fs::create_directories(fs::path(directory) / "vtu");
    vtkNew<vtkCellArray> lines;
    for (const ElementSpec& e : model.elements) {
        const vtkIdType ids[2] = {e.node_i, e.node_j};
        lines->InsertNextCell(2, ids);
    }
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(static_cast<vtkIdType>(model.nodes.size()));
    impl_->grid->SetPoints(points);
    impl_->grid->SetCells(VTK_LINE, lines);
    impl_->writer->SetInputData(impl_->grid);
    const auto [load_unit, displacement_unit] = reported_units(model);
    units_ = {load_unit, displacement_unit};
    write_base();
}

VtuSeriesWriter::~VtuSeriesWriter() = default;
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
    if (pending_) write_step(*pending_);
    pending_.reset();
}

void VtuSeriesWriter::write_step(const StepResult& r) {
    const Model& m = *model_;
    const vtkIdType n = static_cast<vtkIdType>(m.nodes.size());
    const vtkIdType ne = static_cast<vtkIdType>(m.elements.size());
    vtkUnstructuredGrid* grid = impl_->grid;
    vtkPoints* points = grid->GetPoints();
    auto displacement = make_array("displacement", 3, n);
    auto rotation = make_array("rotation", 1, n);
    auto initial = make_array("initial_position", 3, n);
    for (vtkIdType i = 0; i < n; ++i) {
        const double ux = r.displacement[3 * i], uy = r.displacement[3 * i + 1];
        points->SetPoint(i, m.nodes[i].x + ux, m.nodes[i].y + uy, 0.0);
        displacement->SetTuple3(i, ux, uy, 0.0);
        rotation->SetValue(i, r.displacement[3 * i + 2]);
        initial->SetTuple3(i, m.nodes[i].x, m.nodes[i].y, 0.0);
    }
    points->Modified();

    vtkPointData* pd = grid->GetPointData();
    pd->Initialize();
    pd->AddArray(displacement);
    pd->SetActiveVectors("displacement");
    pd->AddArray(rotation);
    pd->AddArray(initial);

    // Nodal bending moment: the mean of the element-end moments meeting at the node.
    auto moment = make_array("bending_moment", 1, n);
    std::vector<int> count(n, 0);
    vtkCellData* cd = grid->GetCellData();
    cd->Initialize();
    auto axial = make_array("axial_force", 1, ne);
    auto mi = make_array("moment_i", 1, ne);
    auto mj = make_array("moment_j", 1, ne);
    auto shear = make_array("shear", 1, ne);
    for (vtkIdType e = 0; e < ne; ++e) {
        const BeamForces& f = r.elements[e].forces;
        axial->SetValue(e, f.axial);
        mi->SetValue(e, f.moment_i);
        mj->SetValue(e, f.moment_j);
        shear->SetValue(e, f.shear);
        const ElementSpec& spec = m.elements[e];
        moment->SetValue(spec.node_i, moment->GetValue(spec.node_i) + f.moment_i);
        moment->SetValue(spec.node_j, moment->GetValue(spec.node_j) + f.moment_j);
        ++count[spec.node_i];
        ++count[spec.node_j];
    }
    for (vtkIdType i = 0; i < n; ++i)
        if (count[i] > 0) moment->SetValue(i, moment->GetValue(i) / count[i]);
    pd->AddArray(moment);
    cd->AddArray(axial);
    cd->AddArray(mi);
    cd->AddArray(mj);
    cd->AddArray(shear);

    // What holds and what pushes: reactions at supported and prescribed DOFs (the force on the
    // structure), which DOFs each node's support fixes (bits 1 ux, 2 uy, 4 rz), and the applied
    // load λF (with pressure as it follows the members).
    if (!m.supports.empty() || !m.prescribed.empty()) {
        auto reaction = make_array("reaction", 3, n);
        for (vtkIdType i = 0; i < n; ++i)
            reaction->SetTuple3(i, r.reaction[3 * i], r.reaction[3 * i + 1], r.reaction[3 * i + 2]);
        pd->AddArray(reaction);
    }
    if (!m.supports.empty()) {
        vtkNew<vtkIntArray> fixed;
        fixed->SetName("support");
        fixed->SetNumberOfTuples(n);
        std::fill_n(fixed->GetPointer(0), n, 0);
        for (const Support& s : m.supports)
            fixed->SetValue(s.node, fixed->GetValue(s.node) | (s.fixed[0] ? 1 : 0) | (s.fixed[1] ? 2 : 0) | (s.fixed[2] ? 4 : 0));
        pd->AddArray(fixed);
    }
    if (!m.loads.empty() || !m.pressures.empty()) {
        auto applied = make_array("applied_load", 3, n);
        for (vtkIdType i = 0; i < n; ++i)
            applied->SetTuple3(i, r.applied_load[3 * i], r.applied_load[3 * i + 1], r.applied_load[3 * i + 2]);
        pd->AddArray(applied);
    }
    if (has_bilateral(m)) {
        auto spring = make_array("spring_force", 3, n);
        for (const SpringResult& s : r.springs)
            if (!s.unilateral) spring->SetTuple3(s.node, s.force[0], s.force[1], s.force[2]);
        pd->AddArray(spring);
    }
    if (m.has_unilateral_base()) {
        auto contact = make_array("contact_force", 3, n);
        auto gap = make_array("gap", 1, n);
        vtkNew<vtkIntArray> state;
        state->SetName("contact");
        state->SetNumberOfTuples(n);
        std::fill_n(state->GetPointer(0), n, 0);
        for (const SpringResult& s : r.springs) {
            if (!s.unilateral) continue;
            contact->SetTuple3(s.node, s.force[0], s.force[1], 0.0);
            gap->SetValue(s.node, s.gap);
            state->SetValue(s.node, s.active ? 1 : 0);
        }
        pd->AddArray(contact);
        pd->AddArray(gap);
        pd->AddArray(state);
    }
    if (m.has_plasticity(Plasticity::distributed)) {
        // One tuple per element, one component per integration point (ξ order); elements
        // without fibre sections along them carry zeros.
        const int points = m.integration_points();
        auto most = make_array("yielded_share", 1, ne);
        auto share = make_array("section_yielded_share", points, ne);
        auto curvature = make_array("section_curvature", points, ne);
        auto moment_at = make_array("section_moment", points, ne);
        for (vtkIdType e = 0; e < ne; ++e) {
            const std::vector<SectionReport>& sections = r.elements[e].sections;
            double largest = 0.0;
            for (int k = 0; k < points; ++k) {
                const bool has = k < static_cast<int>(sections.size());
                share->SetComponent(e, k, has ? sections[k].yielded_share : 0.0);
                curvature->SetComponent(e, k, has ? sections[k].curvature : 0.0);
                moment_at->SetComponent(e, k, has ? sections[k].moment : 0.0);
                if (has) largest = std::max(largest, sections[k].yielded_share);
            }
            most->SetValue(e, largest);
        }
        cd->AddArray(most);
        cd->AddArray(share);
        cd->AddArray(curvature);
        cd->AddArray(moment_at);
    }
    if (m.has_plasticity(Plasticity::hinges)) {
        auto util = make_array("plastic_utilisation", 1, n);
        vtkNew<vtkIntArray> hinge;
        hinge->SetName("hinge_state");
        hinge->SetNumberOfTuples(n);
        std::fill_n(hinge->GetPointer(0), n, 0);
        auto ei = make_array("ei_ratio", 1, ne);
        auto ui = make_array("utilisation_i", 1, ne);
        auto uj = make_array("utilisation_j", 1, ne);
        vtkNew<vtkIntArray> end_state[2];
        end_state[0]->SetName("hinge_state_i");
        end_state[1]->SetName("hinge_state_j");
        for (auto& s : end_state) {
            s->SetNumberOfTuples(ne);
            std::fill_n(s->GetPointer(0), ne, 0);
        }
        for (vtkIdType e = 0; e < ne; ++e) {
            const ElementResult& er = r.elements[e];
            if (!er.hinged) {
                ei->SetValue(e, 1.0);
                continue;
            }
            ei->SetValue(e, std::min(er.hinge[0].ei_ratio, er.hinge[1].ei_ratio));
            ui->SetValue(e, er.hinge[0].utilisation);
            uj->SetValue(e, er.hinge[1].utilisation);
            end_state[0]->SetValue(e, static_cast<int>(er.hinge[0].state));
            end_state[1]->SetValue(e, static_cast<int>(er.hinge[1].state));
            const int nodes[2] = {m.elements[e].node_i, m.elements[e].node_j};
            for (int end = 0; end < 2; ++end) {
                util->SetValue(nodes[end], std::max(util->GetValue(nodes[end]), er.hinge[end].utilisation));
                hinge->SetValue(nodes[end], std::max(hinge->GetValue(nodes[end]), static_cast<int>(er.hinge[end].state)));
            }
        }
        pd->AddArray(util);
        pd->AddArray(hinge);
        cd->AddArray(ei);
        cd->AddArray(ui);
        cd->AddArray(uj);
        cd->AddArray(end_state[0]);
        cd->AddArray(end_state[1]);
    }

    const double time = options_.time == SeriesTime::step ? static_cast<double>(r.step) : r.arc_length;
    vtkFieldData* fd = grid->GetFieldData();
    fd->Initialize();
    add_field(fd, "TimeValue", time);
    add_field(fd, "load_factor", r.load_factor);
    add_field(fd, "load", r.load);
    add_field(fd, "control_displacement", r.control_displacement);
    add_field(fd, "step", r.step);
    add_field(fd, "iterations", r.iterations);
    add_field(fd, "contact_count", r.contact_count);
    add_field(fd, "hinge_count", r.hinge_count);
    // Names for pictures: the render stage reads them from here, not from the scene file.
    std::vector<std::pair<const char*, const std::string*>> names = {
        {"scene", &m.name}, {"title", &m.title},
        {"load_label", &m.report.load_label}, {"displacement_label", &m.report.displacement_label}};
    // Units, when the scene names them: those of the reported load and displacement follow from
    // what they measure.
    if (!m.report.length_unit.empty() || !m.report.force_unit.empty()) {
        names.push_back({"length_unit", &m.report.length_unit});
        names.push_back({"force_unit", &m.report.force_unit});
        names.push_back({"load_unit", &units_.load});
        names.push_back({"displacement_unit", &units_.displacement});
    }
    if (m.report.mirror_x) add_field(fd, "mirror_x", *m.report.mirror_x);
    for (const auto& [key, value] : names) {
        vtkNew<vtkStringArray> text;
        text->SetName(key);
        text->InsertNextValue(*value);
        fd->AddArray(text);
    }
    grid->Modified();

    const std::string name = step_file_name(r.step);
    const std::string path = (fs::path(directory_) / "vtu" / name).string();
    if (options_.compression == Compression::none)
        write_file_atomically(path, raw_vtu(grid)); // the lean writer: same format, a fraction of the time
    else
        write_xml(impl_->writer.Get(), path, options_.compression);
    entries_.emplace_back(time, "vtu/" + name);
    append_to_pvd(time, "vtu/" + name);
}

void VtuSeriesWriter::write_base() {
    const Model& m = *model_;
    if (m.springs.empty()) return;
    vtkNew<vtkPolyData> poly;
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    vtkNew<vtkCellArray> lines, verts;
    vtkNew<vtkIntArray> kind; // 0 spring anchor, 1 rigid base
    kind->SetName("kind");
    for (const FoundationSpring& s : m.springs) {
        if (s.unilateral) continue; // a base line holds these (drawn below); a tensionless bed shows by its contact forces
        const vtkIdType id = points->InsertNextPoint(m.nodes[s.node].x, m.nodes[s.node].y, 0.0);
        verts->InsertNextCell(1, &id);
    }
    if (m.base) {
        // The rigid line, long enough for a structure that spreads over it: twice the
        // structure's extent on either side of its centre.
        double lo = 1e300, hi = -1e300;
        const double tx = -m.base->normal[1], ty = m.base->normal[0];
        for (const Node& nd : m.nodes) {
            const double t = (nd.x - m.base->point[0]) * tx + (nd.y - m.base->point[1]) * ty;
            lo = std::min(lo, t);
            hi = std::max(hi, t);
        }
        const double mid = 0.5 * (lo + hi), half = std::max(hi - lo, 1e-12);
        const vtkIdType a = points->InsertNextPoint(m.base->point[0] + (mid - 2 * half) * tx, m.base->point[1] + (mid - 2 * half) * ty, 0.0);
        const vtkIdType b = points->InsertNextPoint(m.base->point[0] + (mid + 2 * half) * tx, m.base->point[1] + (mid + 2 * half) * ty, 0.0);
        const vtkIdType ids[2] = {a, b};
        lines->InsertNextCell(2, ids);
    }
    poly->SetPoints(points);
    poly->SetVerts(verts);
    poly->SetLines(lines);
    for (vtkIdType i = 0; i < verts->GetNumberOfCells(); ++i) kind->InsertNextValue(0);
    for (vtkIdType i = 0; i < lines->GetNumberOfCells(); ++i) kind->InsertNextValue(1);
    poly->GetCellData()->AddArray(kind);
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(poly);
    write_xml(writer.Get(), (fs::path(directory_) / "base.vtp").string());
    has_base_file_ = true;
}

void VtuSeriesWriter::append_to_pvd(double time, const std::string& file) {
    static const char closing[] = "  </Collection>\n</VTKFile>\n";
    if (!pvd_) {
        // Created whole through a temporary file and a rename, then kept open.
        write_file_atomically(pvd_path_, "<?xml version=\"1.0\"?>\n"
                                         "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
                                         "  <Collection>\n" + std::string(closing));
        pvd_.reset(std::fopen(pvd_path_.c_str(), "r+b"));
        if (!pvd_) throw std::runtime_error("cannot open " + pvd_path_);
        std::fseek(pvd_.get(), 0, SEEK_END);
        pvd_tail_ = std::ftell(pvd_.get()) - static_cast<long>(sizeof closing - 1);
    }
    std::ostringstream x;
    x.precision(17);
    x << "    <DataSet timestep=\"" << time << "\" group=\"\" part=\"0\" file=\"" << file << "\"/>\n";
    if (has_base_file_) x << "    <DataSet timestep=\"" << time << "\" group=\"\" part=\"1\" file=\"base.vtp\"/>\n";
    const std::string entry = x.str();
    // One write of the new entries and the closing tags over the old closing tags: the file
    // is a complete collection before and after it.
    const std::string tail = entry + closing;
    if (std::fseek(pvd_.get(), pvd_tail_, SEEK_SET) != 0 ||
        std::fwrite(tail.data(), 1, tail.size(), pvd_.get()) != tail.size() || std::fflush(pvd_.get()) != 0)
        throw std::runtime_error("cannot write " + pvd_path_);
    pvd_tail_ += static_cast<long>(entry.size());
}

} // namespace plastica

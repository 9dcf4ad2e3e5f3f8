#include "result_series.hpp"

#include "bounded_file.hpp"
#include "safe_names.hpp"
#include "toml_table_reader.hpp"
#include "vtu_reader.hpp"
#include "render_error.hpp"

#include <vtkAbstractArray.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkOutputWindow.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkStringOutputWindow.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUtilities.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <sstream>

namespace fs = std::filesystem;

namespace plastica::render {

namespace {

// Collects what VTK's readers and parser say while it lives, instead of printing it, so that a
// bad file gives one message naming it rather than a page of VTK diagnostics.
class VtkMessages {
public:
    VtkMessages() : previous_(vtkOutputWindow::GetInstance()) {
        previous_->Register(nullptr);
        vtkOutputWindow::SetInstance(capture_);
        // VTK also sends each error to its logger, which prints to stderr.
        vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
    }
    ~VtkMessages() {
        vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_WARNING);
        vtkOutputWindow::SetInstance(previous_);
        previous_->UnRegister(nullptr);
    }
    // The first message VTK reported, without its "ERROR: In file, line" header and class prefix.
    std::string first() const {
        std::istringstream lines(capture_->GetOutput());
        for (std::string line; std::getline(lines, line);) {
            if (line.empty() || line.rfind("ERROR", 0) == 0 || line.rfind("Warning", 0) == 0) continue;
            const auto prefix = line.find("): ");
            return prefix == std::string::npos ? line : line.substr(prefix + 3);
        }
        return "no message";
    }
    bool any_error() const { return std::string(capture_->GetOutput()).find("ERROR") != std::string::npos; }

private:
    vtkOutputWindow* previous_;
    vtkNew<vtkStringOutputWindow> capture_;
};

// One VTK XML file through its reader, every failure as one RenderError naming the file.
template <class Reader, class Data>
vtkSmartPointer<Data> read_xml(const std::string& file, const char* kind) {
    VtkMessages messages;
    vtkNew<Reader> reader;
    if (!reader->CanReadFile(file.c_str()))
        throw RenderError(file + ": not a " + kind + " file");
    reader->SetFileName(file.c_str());
    reader->Update();
    if (reader->GetErrorCode() != 0 || messages.any_error())
        throw RenderError(file + ": unreadable (" + (messages.any_error() ? messages.first() : "truncated or corrupt") + ")");
    auto copy = vtkSmartPointer<Data>::New();
    copy->ShallowCopy(reader->GetOutput());
    return copy;
}

void require_file(const std::string& file, const std::string& listed_in) {
    std::error_code ec;
    if (!fs::is_regular_file(file, ec))
        throw RenderError(file + ": missing" + (listed_in.empty() ? "" : " (listed in " + listed_in + ")"));
    if (fs::file_size(file, ec) > result_file_limit)
        throw RenderError(file + ": larger than the " + std::to_string(result_file_limit >> 20) + " MiB a result file may have");
}

// A file a collection lists: a plain name inside the collection's folder, reached without a
// symbolic link, so that a crafted .pvd cannot make the drawing read files elsewhere.
void require_file_inside(const std::string& folder, const std::string& file, const std::string& listed_in) {
    const std::string path = (fs::path(folder) / file).string();
    if (!is_plain_relative_path(file)) throw RenderError(file + ": outside the series' folder (listed in " + listed_in + ")");
    std::error_code ec;
    if (fs::exists(fs::symlink_status(path, ec)) && !is_file_inside(folder, file))
        throw RenderError(path + ": reached through a symbolic link, not read (listed in " + listed_in + ")");
    require_file(path, listed_in);
}

std::string find_pvd(const std::string& folder) {
    std::vector<std::string> found;
    for (const auto& entry : fs::directory_iterator(folder))
        if (entry.path().extension() == ".pvd" && entry.symlink_status().type() == fs::file_type::regular)
            found.push_back(entry.path().string());
    if (found.size() != 1)
        throw RenderError(folder + ": expected one .pvd result series, found " + std::to_string(found.size()));
    return found.front();
}

} // namespace

ResultSeries open_series(const std::string& folder_or_pvd) {
    std::error_code ec;
    ResultSeries series;
    if (fs::is_directory(folder_or_pvd, ec))
        series.pvd = find_pvd(folder_or_pvd);
    else
        series.pvd = folder_or_pvd;
    require_file(series.pvd, "");
    series.folder = fs::path(series.pvd).parent_path().string();
    if (series.folder.empty()) series.folder = ".";

    VtkMessages messages;
    std::unique_ptr<vtkXMLDataElement, void (*)(vtkXMLDataElement*)> root(
        vtkXMLUtilities::ReadElementFromFile(series.pvd.c_str()), [](vtkXMLDataElement* e) { if (e) e->Delete(); });
    if (!root)
        throw RenderError(series.pvd + ": not readable XML" + (messages.any_error() ? " (" + messages.first() + ")" : ""));
    const char* type = root->GetAttribute("type");
    vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
    if (std::string(root->GetName()) != "VTKFile" || !type || std::string(type) != "Collection" || !collection)
        throw RenderError(series.pvd + ": not a ParaView collection (expected <VTKFile type=\"Collection\">)");
    for (int i = 0; i < collection->GetNumberOfNestedElements(); ++i) {
        vtkXMLDataElement* item = collection->GetNestedElement(i);
        const char* file = item->GetAttribute("file");
        double time = 0.0;
        if (std::string(item->GetName()) != "DataSet" || !file || !item->GetScalarAttribute("timestep", time))
            throw RenderError(series.pvd + ": DataSet " + std::to_string(i + 1) + " has no file or timestep");
        require_file_inside(series.folder, file, series.pvd);
        const std::string path = (fs::path(series.folder) / file).string();
        int part = 0;
        item->GetScalarAttribute("part", part);
        if (part == 1) {
            series.base_file = path;
            continue;
        }
        if (!series.steps.empty() && time <= series.steps.back().time)
            throw RenderError(series.pvd + ": times must increase (" + file + ")");
        series.steps.push_back({time, path});
    }
    if (series.steps.empty()) throw RenderError(series.pvd + ": lists no steps");
    return series;
}

vtkSmartPointer<vtkUnstructuredGrid> read_step(const std::string& file) {
    // VTK's reader trusts the sizes the appended data's headers claim (2⁶³ bytes: a crash inside
    // it): Plastica's own reader checks every offset and size against the file first.
    try {
        (void)parse_unstructured_grid(read_bounded_file(file, result_file_limit), file);
    } catch (const std::runtime_error& e) {
        throw RenderError(std::string(e.what()) + " (not a step file as Plastica writes it)");
    }
    auto grid = read_xml<vtkXMLUnstructuredGridReader, vtkUnstructuredGrid>(file, "VTK unstructured grid (.vtu)");
    if (grid->GetNumberOfPoints() == 0)
        throw RenderError(file + ": holds no points");
    vtkPointData* pd = grid->GetPointData();
    for (const char* name : {"displacement", "initial_position"})
        if (!pd->GetArray(name))
            throw RenderError(file + ": no point array '" + name + "' (not a Plastica result)");
    for (const char* name : {"load", "control_displacement", "step"})
        if (!grid->GetFieldData()->GetArray(name))
            throw RenderError(file + ": no field data '" + name + "' (not a Plastica result)");
    return grid;
}

vtkSmartPointer<vtkPolyData> read_base(const std::string& file) {
    return read_xml<vtkXMLPolyDataReader, vtkPolyData>(file, "VTK polydata (.vtp)");
}

double field_value(vtkUnstructuredGrid* grid, const char* name) {
    vtkDataArray* a = grid->GetFieldData()->GetArray(name);
    if (!a || a->GetNumberOfTuples() < 1) throw RenderError(std::string("no field data '") + name + "'");
    return a->GetComponent(0, 0);
}

std::string field_text(vtkUnstructuredGrid* grid, const char* name, const std::string& fallback) {
    auto* a = vtkStringArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray(name));
    if (!a || a->GetNumberOfValues() == 0) return fallback;
    // A series from elsewhere may hold any text: one line of a bounded length is drawn.
    std::string text = a->GetValue(0).substr(0, max_text_bytes);
    for (char& c : text)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
    return text;
}

} // namespace plastica::render

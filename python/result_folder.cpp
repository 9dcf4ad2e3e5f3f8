// plastica.open: an output folder that `plastica run` (or Result.write) wrote, read as the run
// it came from. run.json and curve.csv are read at once, each step's VTU when asked for. The
// folder may be someone else's (a CI artefact): every file is read inside it, never through a
// symbolic link, within the result files' size limit, and the series' file names must be plain.
#include "bounded_file.hpp"
#include "numpy_arrays.hpp"
#include "safe_names.hpp"
#include "scene_error.hpp"
#include "vtu_reader.hpp"

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace plastica {

namespace {

namespace fs = std::filesystem;

class ResultFolder {
public:
    explicit ResultFolder(const std::string& folder) : folder_(folder) {
        if (!fs::is_directory(folder)) throw std::invalid_argument(folder + ": not a folder");
        report_json_ = read("run.json");
        curve_csv_ = read("curve.csv");
        for (const fs::directory_entry& e : fs::directory_iterator(folder))
            if (e.path().extension() == ".pvd" && e.is_regular_file() && !e.is_symlink()) {
                if (!collection_.empty()) throw std::invalid_argument(folder + ": more than one .pvd collection");
                collection_ = e.path().filename().string();
            }
        if (!collection_.empty()) steps_ = step_files(read(collection_));
    }

    const std::string& report_json() const { return report_json_; }
    const std::string& curve_csv() const { return curve_csv_; }
    std::size_t step_count() const { return steps_.size(); }
    const std::string& folder() const { return folder_; }

    py::dict step_arrays(int k) const {
        if (k < 0) k += static_cast<int>(steps_.size());
        if (k < 0 || k >= static_cast<int>(steps_.size()))
            throw py::index_error(steps_.empty() ? folder_ + ": no VTU series (written with --no-series?)" : "no step " + std::to_string(k));
        const std::string& file = steps_[static_cast<std::size_t>(k)];
        XmlDataset grid;
        {
            py::gil_scoped_release unlocked;
            grid = parse_unstructured_grid(read(file), (fs::path(folder_) / file).string());
        }
        return dataset_arrays(grid);
    }

private:
    std::string read(const std::string& relative) const {
        try {
            return read_file_inside(folder_, relative, result_file_limit);
        } catch (const FileReadError& e) {
            throw std::invalid_argument(e.what());
        }
    }

    // The structure's files a PVD collection names, in its order: plain relative paths only.
    std::vector<std::string> step_files(const std::string& pvd) const {
        std::vector<std::string> files;
        const std::string key = " file=\"";
        for (std::size_t at = pvd.find("<DataSet"); at != std::string::npos; at = pvd.find("<DataSet", at + 1)) {
            const std::size_t end = pvd.find('>', at);
            const std::size_t start = pvd.find(key, at);
            if (end == std::string::npos || start == std::string::npos || start > end) throw std::invalid_argument(collection_ + ": a DataSet names no file");
            const std::size_t close = pvd.find('"', start + key.size());
            const std::string file = pvd.substr(start + key.size(), close - start - key.size());
            if (!is_plain_relative_path(file)) throw std::invalid_argument(collection_ + ": '" + file + "' is not a file inside the folder");
            // Part 0 is the structure; other parts are the bases and walls beside it.
            const std::size_t part = pvd.find(" part=\"", at);
            if (part != std::string::npos && part < end && pvd.compare(part, 9, " part=\"0\"") != 0) continue;
            files.push_back(file);
        }
        return files;
    }

    std::string folder_;
    std::string report_json_, curve_csv_;
    std::string collection_;
    std::vector<std::string> steps_;
};

} // namespace

void bind_result_folder(py::module_& m) {
    py::register_exception<VtuReadError>(m, "ResultFileError", PyExc_ValueError);
    py::class_<ResultFolder, std::shared_ptr<ResultFolder>>(m, "ResultFolder")
        .def(py::init<const std::string&>(), py::arg("folder"))
        .def_property_readonly("report_json", &ResultFolder::report_json)
        .def_property_readonly("curve_csv", &ResultFolder::curve_csv)
        .def_property_readonly("step_count", &ResultFolder::step_count)
        .def_property_readonly("folder", &ResultFolder::folder)
        .def("step_arrays", &ResultFolder::step_arrays, py::arg("k"));
}

} // namespace plastica

#include "output_folder.hpp"

#include "run_report.hpp"

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace plastica::cli {

namespace fs = std::filesystem;

std::string default_output_folder(const std::string& scene_name) {
    return (fs::path("out") / scene_name).string();
}


void prepare_output_folder(const std::string& folder, const std::string& scene_name, bool force, bool keep_step_files) {
    const fs::path dir(folder);
    if (fs::exists(dir) && !fs::is_directory(dir))
        throw std::runtime_error("output path " + folder + " exists and is not a folder");
    if (fs::exists(dir)) {
        const std::string other = recorded_scene((dir / "run.json").string());
        const bool foreign = !other.empty() && other != scene_name;
        const bool unknown = other.empty() && !fs::is_empty(dir);
        if ((foreign || unknown) && !force)
            throw std::runtime_error("output folder " + folder + " holds " +
                                     (foreign ? "results of scene '" + other + "'" : "files of another program") +
                                     "; choose another folder with -o or pass --force to replace them");
        // Results of an earlier run: remove them so no stale step joins the new series.
        fs::remove_all(dir / "frames");
        if (!keep_step_files) fs::remove_all(dir / "vtu");
        for (const auto& entry : fs::directory_iterator(dir)) {
            const std::string ext = entry.path().extension().string();
            if (ext == ".pvd" || ext == ".vtp" || ext == ".csv" || ext == ".json" || ext == ".png" || ext == ".gif")
                fs::remove(entry.path());
        }
    }
    fs::create_directories(dir);
}

} // namespace plastica::cli

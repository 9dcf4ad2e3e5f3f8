#include "render_stage.hpp"

#include "progress.hpp"
#include "interruption.hpp"
#include "render_error.hpp"

#include "atomic_file.hpp"
#include "output_folder.hpp"

#include <filesystem>
#include <iostream>

namespace plastica::cli {

std::string pictures_folder(const std::string& series, const render::RenderOptions& options) {
    namespace fs = std::filesystem;
    if (!options.output.empty()) return options.output;
    const std::string folder = fs::is_directory(series) ? series : fs::path(series).parent_path().string();
    return folder.empty() ? std::string(".") : folder;
}

int render_and_report(const std::string& series, const render::RenderOptions& options, std::vector<std::string>* notes) {
    // SIGINT and SIGTERM stop the drawing between frames; its temporary files go with it.
    const render::StopOnSignal stop_on_signal;
    const std::string output = pictures_folder(series, options);
    try {
        render::RenderOptions with_progress = options;
        Progress progress("drawing", 25, "frames");
        if (!options.quiet)
            with_progress.on_frame = [&progress](int done, int total) {
                progress.update(done, static_cast<double>(done) / total, "frame " + std::to_string(done) + " of " + std::to_string(total));
            };
        const render::RenderReport r = render::render_series(series, with_progress);
        progress.finish();
        for (const std::string& note : r.notes) std::cerr << "plastica: note: " << note << "\n";
        if (notes) notes->insert(notes->end(), r.notes.begin(), r.notes.end());
        if (!options.quiet) {
            std::cerr << "rendered " << r.frames << " frames in " << r.seconds << " s (" << r.frames_per_second
                      << " frames per second, " << r.workers << (r.workers == 1 ? " process, " : " processes, ")
                      << r.gl_renderer << ") into " << r.output << "/frames\n";
            std::cerr << r.output << "/chart.png, " << r.output << "/contact_sheet.png; " << r.animation << "\n";
        }
    } catch (const render::RenderInterrupted&) {
        // The caller holds the folder's lock: what a killed worker left is this drawing's.
        if (std::filesystem::is_directory(output)) remove_stale_temporaries(output);
        std::cerr << "plastica: drawing interrupted; the frames drawn so far are kept\n";
        return interrupted;
    } catch (const WriteError& e) {
        std::cerr << "plastica: cannot write the pictures: " << e.what() << "\n";
        return stopped_early;
    } catch (const render::RenderError& e) {
        std::cerr << "plastica: cannot render: " << e.what() << "\n";
        return bad_input;
    } catch (const std::exception& e) {
        std::cerr << "plastica: cannot render " << series << ": " << e.what() << "\n";
        return bad_input;
    }
    return ok;
}

} // namespace plastica::cli

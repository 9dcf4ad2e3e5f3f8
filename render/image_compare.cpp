#include "image_compare.hpp"
#include "png_file.hpp"
#include "render_error.hpp"

#include <vtkImageData.h>
#include <vtkImageDifference.h>
#include <vtkNew.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>

namespace fs = std::filesystem;

namespace plastica::render {

namespace {

std::string dims_text(const int d[3]) { return std::to_string(d[0]) + "x" + std::to_string(d[1]); }

std::set<std::string> pngs_under(const fs::path& folder) {
    std::set<std::string> names;
    // Regular files only, never through a symbolic link: a folder from elsewhere is read inside itself.
    for (const auto& entry : fs::recursive_directory_iterator(folder))
        if (entry.symlink_status().type() == fs::file_type::regular && entry.path().extension() == ".png")
            names.insert(entry.path().lexically_relative(folder).generic_string());
    return names;
}

// Red where the pixels differ, elsewhere the reference faded towards white.
void write_diff(vtkImageData* reference, const std::vector<bool>& differs, const std::string& path) {
    int d[3];
    reference->GetDimensions(d);
    const int c = reference->GetNumberOfScalarComponents();
    vtkNew<vtkImageData> diff;
    diff->SetDimensions(d[0], d[1], 1);
    diff->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    const auto* ref = static_cast<unsigned char*>(reference->GetScalarPointer());
    auto* out = static_cast<unsigned char*>(diff->GetScalarPointer());
    for (std::size_t i = 0; i < differs.size(); ++i) {
        for (int k = 0; k < 3; ++k) {
            const unsigned char v = ref[i * c + std::min(k, c - 1)];
            out[3 * i + k] = differs[i] ? (k == 0 ? 255 : 0) : static_cast<unsigned char>(255 - (255 - v) / 4);
        }
    }
    fs::create_directories(fs::path(path).parent_path());
    write_png(diff, path);
}

ImageVerdict compare_one(const std::string& name, const std::string& actual_path, const std::string& reference_path,
                         const CompareOptions& options) {
    ImageVerdict v;
    v.name = name;
    auto actual = read_png(actual_path);
    auto reference = read_png(reference_path);
    int da[3], dr[3];
    actual->GetDimensions(da);
    reference->GetDimensions(dr);
    if (da[0] != dr[0] || da[1] != dr[1])
        throw RenderError(actual_path + ": size mismatch, " + dims_text(da) + " against the reference's " + dims_text(dr));
    const int ca = actual->GetNumberOfScalarComponents(), cr = reference->GetNumberOfScalarComponents();
    const auto* a = static_cast<unsigned char*>(actual->GetScalarPointer());
    const auto* r = static_cast<unsigned char*>(reference->GetScalarPointer());
    const std::size_t n = static_cast<std::size_t>(da[0]) * da[1];
    std::vector<bool> differs(n, false);
    std::size_t count = 0, compared = 0;
    double sum = 0.0;
    const int x0 = static_cast<int>(options.region[0] * da[0]), x1 = static_cast<int>(options.region[2] * da[0]);
    const int y0 = static_cast<int>(options.region[1] * da[1]), y1 = static_cast<int>(options.region[3] * da[1]);
    for (std::size_t i = 0; i < n; ++i) {
        // VTK's rows start at the bottom of the picture.
        const int x = static_cast<int>(i % da[0]), y = da[1] - 1 - static_cast<int>(i / da[0]);
        if (x < x0 || x >= x1 || y < y0 || y >= y1) continue;
        ++compared;
        int worst = 0;
        for (int k = 0; k < 3; ++k) {
            const int delta = std::abs(int(a[i * ca + std::min(k, ca - 1)]) - int(r[i * cr + std::min(k, cr - 1)]));
            worst = std::max(worst, delta);
            sum += double(delta) * delta;
        }
        if (worst > options.threshold) differs[i] = true, ++count;
    }
    v.differing_fraction = double(count) / double(std::max<std::size_t>(compared, 1));
    v.rms = std::sqrt(sum / (3.0 * std::max<std::size_t>(compared, 1)));
    vtkNew<vtkImageDifference> vtk;
    vtk->SetInputData(actual);
    vtk->SetImageData(reference);
    vtk->Update();
    v.vtk_error = vtk->GetThresholdedError();
    v.passed = v.differing_fraction <= options.max_fraction;
    if (!v.passed && !options.diff_folder.empty()) {
        std::string stem = name;
        stem = stem.substr(0, stem.size() - 4);
        write_diff(reference, differs, (fs::path(options.diff_folder) / (stem + "_diff.png")).string());
    }
    return v;
}

} // namespace

std::vector<ImageVerdict> compare_pictures(const std::string& actual, const std::string& reference,
                                           const CompareOptions& options) {
    std::error_code ec;
    for (const std::string& p : {actual, reference})
        if (!fs::exists(p, ec)) throw RenderError(p + ": missing");
    if (options.threshold < 0 || options.threshold > 255) throw RenderError("--threshold takes 0 … 255");
    if (!(options.max_fraction >= 0.0 && options.max_fraction <= 1.0)) throw RenderError("--max-fraction takes 0 … 1");
    const double* g = options.region;
    if (!(g[0] >= 0.0 && g[0] < g[2] && g[2] <= 1.0 && g[1] >= 0.0 && g[1] < g[3] && g[3] <= 1.0))
        throw RenderError("--region takes x0,y0,x1,y1: fractions of the width and height, 0 ≤ x0 < x1 ≤ 1, 0 ≤ y0 < y1 ≤ 1");
    const bool folders = fs::is_directory(actual, ec);
    if (folders != fs::is_directory(reference, ec))
        throw RenderError("compare two PNG files or two folders, not a file with a folder");
    if (!folders) return {compare_one(fs::path(actual).filename().string(), actual, reference, options)};

    const auto have = pngs_under(actual), want = pngs_under(reference);
    std::vector<ImageVerdict> verdicts;
    std::set<std::string> all = have;
    all.insert(want.begin(), want.end());
    for (const std::string& name : all) {
        if (!have.count(name)) {
            verdicts.push_back({name, false, 1.0, 0.0, 0.0, "missing in " + actual});
        } else if (!want.count(name)) {
            verdicts.push_back({name, false, 1.0, 0.0, 0.0, "extra: no reference in " + reference});
        } else {
            verdicts.push_back(compare_one(name, (fs::path(actual) / name).string(), (fs::path(reference) / name).string(), options));
        }
    }
    if (verdicts.empty()) throw RenderError(reference + ": no PNG images to compare");
    return verdicts;
}

} // namespace plastica::render

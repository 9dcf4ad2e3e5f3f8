#include "text_and_mirror.hpp"
#include "palette.hpp"

#include <vtkActor.h>
#include <vtkStdString.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>
#include <vtkTransform.h>

#include <cmath>
#include <filesystem>

namespace plastica::render {

void use_text_font(vtkTextProperty* p, bool bold) {
    // VTK's built-in Arial has Latin letters only (σ, θ, δ vanish); DejaVu Sans (Debian's
    // fonts-dejavu-core) has Greek and the mathematical signs engineers write in labels.
    static const char* regular = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    static const char* heavy = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf";
    static const bool available = std::filesystem::exists(regular) && std::filesystem::exists(heavy);
    p->SetBold(bold);
    if (!available) {
        p->SetFontFamilyToArial();
        return;
    }
    p->SetFontFamily(VTK_FONT_FILE);
    p->SetFontFile(bold ? heavy : regular);
}

double text_width(vtkTextProperty* p, const std::string& text) {
    int box[4];
    vtkTextRenderer* measure = vtkTextRenderer::GetInstance();
    return measure && measure->GetBoundingBox(p, vtkStdString(text), box, 72) ? box[1] - box[0] : 0.0;
}

void style_text(vtkTextProperty* p, double size, bool bold) {
    use_text_font(p, bold);
    p->SetFontSize(static_cast<int>(std::lround(size)));
    p->SetColor(colour::text.red(), colour::text.green(), colour::text.blue());
    p->SetShadow(false);
}

vtkSmartPointer<vtkActor> mirrored(vtkActor* actor, double mirror_x) {
    vtkNew<vtkTransform> reflect;
    reflect->Translate(mirror_x, 0, 0);
    reflect->Scale(-1, 1, 1);
    reflect->Translate(-mirror_x, 0, 0);
    auto twin = vtkSmartPointer<vtkActor>::New();
    twin->ShallowCopy(actor);
    twin->SetUserTransform(reflect);
    return twin;
}

} // namespace plastica::render

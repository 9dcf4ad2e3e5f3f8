#include "text_and_mirror.hpp"
#include "palette.hpp"

#include <vtkActor.h>
#include <vtkTextProperty.h>
#include <vtkTransform.h>

#include <cmath>

namespace plastica::render {

void style_text(vtkTextProperty* p, double size, bool bold) {
    p->SetFontFamilyToArial();
    p->SetFontSize(static_cast<int>(std::lround(size)));
    p->SetColor(colour::text.red(), colour::text.green(), colour::text.blue());
    p->SetBold(bold);
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

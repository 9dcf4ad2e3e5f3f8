// Two small habits of every picture: text in the palette's text colour (Arial, no shadow), and
// the mirror image of an actor for a half model drawn whole.
#pragma once

#include <string>

#include <vtkSmartPointer.h>

class vtkActor;
class vtkTextProperty;

namespace plastica::render {

void style_text(vtkTextProperty* p, double size, bool bold = false);
// The font of every text: DejaVu Sans where Debian has it installed (Greek letters, signs),
// else VTK's Arial.
void use_text_font(vtkTextProperty* p, bool bold = false);
// The width in pixels the text takes in that property's font (0 if it cannot be measured).
double text_width(vtkTextProperty* p, const std::string& text);

// A copy of the actor drawn reflected about the line x = mirror_x (x → 2·mirror_x − x).
vtkSmartPointer<vtkActor> mirrored(vtkActor* actor, double mirror_x);

} // namespace plastica::render

#include "arrays/output_array.hpp"

namespace plastica {

// The groups, one file each in io/results/arrays/.
OutputGroup identity_arrays();
OutputGroup kinematic_arrays();
OutputGroup motion_arrays();
OutputGroup member_force_arrays();
OutputGroup support_and_load_arrays();
OutputGroup spring_arrays();
OutputGroup base_contact_arrays();
OutputGroup surface_contact_arrays();
OutputGroup section_arrays();
OutputGroup hinge_arrays();
OutputGroup step_field_arrays();
OutputGroup critical_point_arrays();
OutputGroup base_line_arrays();

const std::vector<OutputGroup>& output_groups() {
    static const std::vector<OutputGroup> groups = {
        identity_arrays(),    kinematic_arrays(),     motion_arrays(), member_force_arrays(),  support_and_load_arrays(), spring_arrays(),
        base_contact_arrays(), surface_contact_arrays(), section_arrays(),        hinge_arrays(),
        step_field_arrays(),  critical_point_arrays(), base_line_arrays(),
    };
    return groups;
}

} // namespace plastica

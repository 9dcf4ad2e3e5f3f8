#include "xml_dataset.hpp"

namespace plastica {

std::size_t XmlArray::tuples() const {
    return std::visit([this](const auto& v) { return v.size() / static_cast<std::size_t>(components); }, values);
}

XmlArray real_array(std::string name, std::size_t tuples, int components) {
    return {std::move(name), components, std::vector<double>(tuples * static_cast<std::size_t>(components), 0.0)};
}

XmlArray integer_array(std::string name, std::size_t tuples) {
    return {std::move(name), 1, std::vector<std::int32_t>(tuples, 0)};
}

XmlArray field_value(std::string name, double value) {
    return {std::move(name), 1, std::vector<double>{value}};
}

XmlArray field_text(std::string name, std::string value) {
    return {std::move(name), 1, std::vector<std::string>{std::move(value)}};
}

} // namespace plastica

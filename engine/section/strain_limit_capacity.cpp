#include "section/strain_limit_capacity.hpp"

#include "section/fibre_section.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <string>

namespace plastica {

std::shared_ptr<const SectionCapacity> build_strain_limit_capacity(const FibreSection& section);

namespace {

struct Faces {
    double compressed = -HUGE_VAL, bottom = HUGE_VAL; // in z = sign·y
    double top = -HUGE_VAL; // of all fibres: above `compressed` where steel without a limit lies beyond the concrete
    double bending_limit = HUGE_VAL, uniform_limit = HUGE_VAL;
    double tension_limit = HUGE_VAL, tension_z = HUGE_VAL; // the lowest fibre with a tensile limit
    double large_strain = 0.0; // "every steel fibre yielded in tension" where no limit says more
};

Faces faces_of(const std::vector<SectionFibre>& fibres, double sign) {
    Faces f;
    for (const SectionFibre& fibre : fibres) {
        const UniaxialMaterial::StrainLimits limits = fibre.material->strain_limits();
        const double z = sign * fibre.y;
        f.bottom = std::min(f.bottom, z - fibre.extent);
        f.top = std::max(f.top, z + fibre.extent);
        if (std::isfinite(limits.bending_compression)) {
            f.compressed = std::max(f.compressed, z + fibre.extent);
            f.bending_limit = std::min(f.bending_limit, limits.bending_compression);
            f.uniform_limit = std::min(f.uniform_limit, limits.uniform_compression);
        }
        if (std::isfinite(limits.tension) && (z < f.tension_z || (z == f.tension_z && limits.tension < f.tension_limit))) {
            f.tension_z = z;
            f.tension_limit = limits.tension;
        }
        if (fibre.limit_tension > 0.0)
            f.large_strain = std::max(f.large_strain, 10.0 * fibre.limit_tension / fibre.material->elastic_modulus());
    }
    return f;
}

} // namespace

std::array<std::vector<LimitState>, 2> strain_limit_states(const FibreSection& section, int points_per_region) {
    std::array<std::vector<LimitState>, 2> states;
    if (!section.has_strain_limits()) return states;
    // Unstressed copies of the laws: a trial strain from the virgin state gives the envelope.
    std::vector<MaterialHolder> laws;
    for (const SectionFibre& f : section.fibres()) laws.emplace_back(f.material->clone());
    const std::vector<SectionFibre>& fibres = section.fibres();
    for (int side = 0; side < 2; ++side) {
        const double sign = side == 0 ? 1.0 : -1.0;
        const Faces f = faces_of(fibres, sign);
        const double h = f.compressed - f.bottom;
        // Fibres all at one height (a list of points) have no depth to bend over.
        if (!(h > 0.0) || !std::isfinite(h)) return {};
        // The strain at z is top + (compressed − z)·k; in the section's terms ε0 − y·κ.
        const auto add = [&](double top, double k) {
            LimitState s;
            s.eps0 = top + f.compressed * k;
            s.curvature = sign * k;
            for (std::size_t i = 0; i < fibres.size(); ++i) {
                const double stress = laws[i]->set_trial_strain(s.eps0 - fibres[i].y * s.curvature).stress;
                s.N += stress * fibres[i].area;
                s.M -= stress * fibres[i].area * fibres[i].y;
            }
            states[side].push_back(s);
        };
        const int n = points_per_region;
        const double ecu = f.bending_limit, ec2 = f.uniform_limit;
        double shallowest; // neutral axis depth where the compressed face reaches εcu2 first
        if (std::isfinite(f.tension_limit) && f.tension_z < f.compressed) {
            // Steel at its limit, the compressed face from the same strain to −εcu2.
            const double d = f.compressed - f.tension_z;
            for (int k = 0; k < n; ++k) {
                const double top = f.tension_limit - (f.tension_limit + ecu) * k / n;
                add(top, (f.tension_limit - top) / d);
            }
            shallowest = ecu * d / (f.tension_limit + ecu);
        } else {
            add(f.large_strain, 0.0); // every fibre with tensile strength at its yield
            shallowest = 1e-4 * h;
        }
        // Fibres without a compressive limit beyond the concrete (a composite beam's steel in
        // hogging): while the neutral axis lies among them, nothing limits the strains, and the
        // states are the fully plastic ones, at the curvature the shallowest limit state has.
        if (f.top > f.compressed) {
            const double k = ecu / shallowest;
            for (int i = 0; i <= 2 * n; ++i) {
                const double neutral_axis = f.top - (f.top - f.compressed) * i / (2 * n);
                add(k * (neutral_axis - f.compressed), k);
            }
        }
        // The compressed face at −εcu2, the neutral axis from the shallowest depth to h: evenly
        // in depth over the last nine tenths (the balanced point lies there), geometrically
        // above them where the curvature grows without bound.
        const double even_from = std::max(shallowest, 0.1 * h);
        for (int k = 0; k < n && even_from > shallowest; ++k)
            add(-ecu, ecu / (shallowest * std::pow(even_from / shallowest, static_cast<double>(k) / n)));
        for (int k = 0; k < 4 * n; ++k) add(-ecu, ecu / (even_from + (h - even_from) * k / (4 * n)));
        // Wholly compressed: the pivot at −εc2, the bottom from 0 to −εc2.
        const double pivot_to_bottom = h * ec2 / ecu;
        for (int k = 0; k <= n; ++k) {
            const double bottom = -ec2 * k / n;
            const double slope = (bottom + ec2) / pivot_to_bottom;
            add(-ec2 - (h - pivot_to_bottom) * slope, slope);
        }
    }
    return states;
}

namespace {

// What the limit states depend on, as bytes: each fibre's area, y, extent, and its law's
// envelope as it stands unstrained (sampled at the strains the states reach).
std::string capacity_key(const FibreSection& section) {
    std::string key;
    const auto put = [&](double v) { key.append(reinterpret_cast<const char*>(&v), sizeof v); };
    for (const SectionFibre& f : section.fibres()) {
        put(f.area);
        put(f.y);
        put(f.extent);
        const MaterialHolder law(f.material->clone());
        const UniaxialMaterial::StrainLimits limits = law->strain_limits();
        put(limits.bending_compression);
        put(limits.uniform_compression);
        put(limits.tension);
        for (double strain : {-0.05, -0.0035, -0.003, -0.0025, -0.002, -0.001, -0.0005, 0.0005, 0.001, 0.002, 0.01, 0.05}) {
            MaterialHolder probe(law);
            put(probe->set_trial_strain(strain).stress);
        }
    }
    return key;
}

} // namespace

std::shared_ptr<const SectionCapacity> strain_limit_capacity(const FibreSection& section) {
    // Every section of the same fibres (both ends of every element of a member) shares one.
    static std::mutex mutex;
    static std::map<std::string, std::weak_ptr<const SectionCapacity>> cache;
    const std::string key = capacity_key(section);
    {
        const std::lock_guard<std::mutex> lock(mutex);
        const auto found = cache.find(key);
        if (found != cache.end())
            if (auto held = found->second.lock()) return held;
    }
    const auto built = build_strain_limit_capacity(section);
    const std::lock_guard<std::mutex> lock(mutex);
    for (auto at = cache.begin(); at != cache.end();) at = at->second.expired() ? cache.erase(at) : std::next(at);
    if (built) cache[key] = built;
    return built;
}

std::shared_ptr<const SectionCapacity> build_strain_limit_capacity(const FibreSection& section) {
    const auto states = strain_limit_states(section);
    if (states[0].empty()) return nullptr;
    std::array<std::vector<CapacityPoint>, 2> polylines;
    for (int side = 0; side < 2; ++side)
        for (const LimitState& s : states[side]) polylines[side].push_back({s.N, s.M});
    return capacity_through_points(std::move(polylines));
}

} // namespace plastica

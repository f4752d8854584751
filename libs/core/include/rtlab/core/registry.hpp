#pragma once
/// \brief Named factories for one base type: how textures, materials and shapes are created by name.
#include <rtlab/core/error.hpp>
#include <rtlab/core/param_spec.hpp>
#include <rtlab/core/params.hpp>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace rtlab {

namespace detail {
[[noreturn]] void throw_unknown_name(std::string_view category, std::string_view name,
                                     const std::vector<std::string>& known);
[[noreturn]] void throw_duplicate_name(std::string_view category, std::string_view name);
}  // namespace detail

/// \brief Maps names ("checker", "phong") to factories that build a Base from Params.
///
/// Libraries fill a registry with an explicit register_builtins(Registry&) call, and plugin modules
/// with their own exported function: no static self-registration, which static linking would drop.
template <class Base>
class Registry {
public:
    using Factory = std::function<std::shared_ptr<Base>(const Params&)>;

    /// category names the kind of object in messages: "texture", "material".
    explicit Registry(std::string category) : m_category(std::move(category)) {}

    const std::string& category() const { return m_category; }

    /// Adds a factory with the declaration of its parameters (what a scene loader checks a file's values
    /// against; required, so that no type goes undeclared); a name registered twice is an error (two plugins fighting
    /// over one name).
    void add(std::string name, Factory factory, TypeSpec spec) {
        if (m_entries.contains(name)) detail::throw_duplicate_name(m_category, name);
        m_entries.emplace(std::move(name), Entry{std::move(factory), std::move(spec)});
    }

    bool contains(std::string_view name) const { return m_entries.find(name) != m_entries.end(); }

    /// Registered names in sorted order.
    std::vector<std::string> names() const {
        std::vector<std::string> out;
        out.reserve(m_entries.size());
        for (const auto& [name, entry] : m_entries) out.push_back(name);
        return out;
    }

    /// One-line documentation given at registration ("" when none).
    const std::string& doc(std::string_view name) const { return entry(name).spec.doc(); }

    /// The parameters the type declared at registration.
    const TypeSpec& spec(std::string_view name) const { return entry(name).spec; }

    /// The factory registered under name: lets a plugin host move a module's registrations into its own
    /// registries once it has checked them all.
    const Factory& factory(std::string_view name) const { return entry(name).factory; }

    /// Builds the named object. Unknown names list the known ones; parameters that the factory did not
    /// read are reported as errors naming the object.
    std::shared_ptr<Base> create(std::string_view name, Params params) const {
        const Entry& e = entry(name);
        params.set_context(m_category + " '" + std::string(name) + "'");
        std::shared_ptr<Base> object = e.factory(params);
        params.check_all_used();
        return object;
    }

private:
    struct Entry {
        Factory factory;
        TypeSpec spec;
    };

    const Entry& entry(std::string_view name) const {
        auto it = m_entries.find(name);
        if (it == m_entries.end()) detail::throw_unknown_name(m_category, name, names());
        return it->second;
    }

    std::string m_category;
    std::map<std::string, Entry, std::less<>> m_entries;
};

}  // namespace rtlab

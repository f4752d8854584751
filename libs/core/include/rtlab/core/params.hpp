#pragma once
/// \brief Named, typed parameters for objects created by name (textures, materials, shapes).
#include <rtlab/core/color.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/core/math.hpp>

#include <any>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <typeinfo>
#include <variant>
#include <vector>

namespace rtlab {

/// \brief A parameter set as read from a scene file. Getters check the type and remember which names
/// were read, so that a misspelt or unused parameter is reported instead of silently ignored.
class Params {
public:
    /// Numbers are stored as double; lists hold vectors and colours; objects hold a std::shared_ptr<T>.
    using Number = double;
    using List = std::vector<double>;
    using Value = std::variant<bool, Number, std::string, List, std::any>;

    Params() = default;

    Params& set(std::string name, Value value);
    /// Stores an object (a nested texture, say) to be read back with get_object<T>.
    template <class T>
    Params& set_object(std::string name, std::shared_ptr<T> object) {
        return set(std::move(name), Value{std::in_place_index<4>, std::any(std::move(object))});
    }

    bool has(std::string_view name) const {
        note_lookup(name);
        return m_values.find(name) != m_values.end();
    }
    std::vector<std::string> names() const;

    float get_float(std::string_view name) const;
    float get_float(std::string_view name, float fallback) const;
    int get_int(std::string_view name) const;
    int get_int(std::string_view name, int fallback) const;
    bool get_bool(std::string_view name, bool fallback) const;
    std::string get_string(std::string_view name) const;
    std::string get_string(std::string_view name, std::string_view fallback) const;
    Vec3 get_vec3(std::string_view name) const;
    Vec3 get_vec3(std::string_view name, const Vec3& fallback) const;
    /// A colour is a list of three numbers or one number (grey).
    RGB get_rgb(std::string_view name) const;
    RGB get_rgb(std::string_view name, const RGB& fallback) const;
    List get_list(std::string_view name) const;

    /// The value stored under name (marked as read), or nullptr: for parameters that accept several kinds,
    /// such as "a colour or a texture".
    const Value* get_value(std::string_view name) const { return find(name); }

    /// The object stored under name, or nullptr when there is none; an object of another type is an error.
    template <class T>
    std::shared_ptr<T> get_object(std::string_view name) const {
        const Value* v = find(name);
        if (!v) return nullptr;
        const auto* any = std::get_if<std::any>(v);
        const auto* object = any ? std::any_cast<std::shared_ptr<T>>(any) : nullptr;
        if (!object) fail_type(name, typeid(T).name());
        return *object;
    }

    /// Every name a getter or has() looked up so far, given or not: what a factory reads, for a test that
    /// compares it with the type's declaration.
    std::vector<std::string> looked_up() const { return {m_looked_up.begin(), m_looked_up.end()}; }

    /// Who these parameters are for ("texture 'checker'"); used in every error message.
    void set_context(std::string context) { m_context = std::move(context); }
    const std::string& context() const { return m_context; }

    /// Throws rtlab::Error naming every parameter that no getter has read.
    void check_all_used() const;

    /// Where a factory's non-fatal notes go (a mesh file's dropped faces, say): a scene loader sets it so
    /// that they reach the user beside the file's position; by default they go nowhere.
    void set_warning_sink(std::function<void(const std::string&)> sink) { m_warn = std::move(sink); }
    void warn(const std::string& message) const {
        if (m_warn) m_warn(message);
    }

private:
    const Value* find(std::string_view name) const;
    void note_lookup(std::string_view name) const;
    const Value& require(std::string_view name) const;
    [[noreturn]] void fail_type(std::string_view name, std::string_view expected) const;

    std::map<std::string, Value, std::less<>> m_values;
    mutable std::set<std::string, std::less<>> m_used;
    mutable std::set<std::string, std::less<>> m_looked_up;
    std::string m_context = "object";
    std::function<void(const std::string&)> m_warn;
};

}  // namespace rtlab

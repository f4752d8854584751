#pragma once
/// \brief What a registered type (a shape, material, texture, light, tone operator, a plugin's too) declares
/// about its parameters. A scene loader checks and converts a file's values by these declarations and knows
/// nothing of any particular type; listings (`--list --verbose`) and the parameter tables of
/// docs/scene-format.md are made from them.
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace rtlab {

/// \brief What kind of value a parameter takes, as a scene file writes it.
enum class ParamKind {
    number,   ///< a number
    integer,  ///< a whole number
    boolean,  ///< true or false
    colour,   ///< one number (grey) or [r, g, b], finite and >= 0
    vector,   ///< [x, y, z], finite: a point or a direction
    numbers,  ///< a list of numbers (a matrix, a size), or one number
    texture,  ///< a colour or a texture: a number, [r, g, b], a texture's name or an inline texture
    scalar,   ///< a number or a texture (read as its channel mean): an exponent, a roughness
    file,     ///< a file name, found beside the scene or on the data path
    folder,   ///< a folder name, found like a file
    word,     ///< one of a fixed set of words
    text,     ///< any string
    shape,    ///< the name of a shape defined earlier
};

/// The kind as a scene file's documentation says it ("colour or texture").
const char* param_kind_name(ParamKind kind);

/// \brief One declared parameter. Built with TypeSpec::add and the chained setters below.
struct ParamSpec {
    std::string name;
    ParamKind kind = ParamKind::number;
    std::string doc;  ///< one line
    bool required = false;
    std::string default_value;  ///< as a file would write it ("0.8", "[0, 1, 0]", "repeat"); "" when none
    double lo = -std::numeric_limits<double>::infinity();  ///< range of a number, integer or scalar
    double hi = std::numeric_limits<double>::infinity();
    std::vector<std::string> words;  ///< the allowed words of a word parameter
    std::string unit;                ///< "degrees", "world units"...; "" when none
    std::string group;               ///< "" for the type's own; else a group of keys many types share
    bool file_part = false;          ///< names (part of) the files a texture reads: a fallback replaces them

    ParamSpec& require() {
        required = true;
        return *this;
    }
    ParamSpec& defaults(std::string text) {
        default_value = std::move(text);
        return *this;
    }
    ParamSpec& range(double low, double high) {
        lo = low;
        hi = high;
        return *this;
    }
    ParamSpec& at_least(double low) {
        lo = low;
        return *this;
    }
    ParamSpec& allow(std::vector<std::string> allowed) {
        words = std::move(allowed);
        return *this;
    }
    ParamSpec& in(std::string u) {
        unit = std::move(u);
        return *this;
    }
    ParamSpec& part_of_files() {
        file_part = true;
        return *this;
    }
};

/// \brief A type's documentation and its parameters, in the order a listing shows them.
class TypeSpec {
public:
    /// Every type is registered with one (Registry::add takes no default), so none goes without a doc.
    explicit TypeSpec(std::string doc) : m_doc(std::move(doc)) {}

    /// Declares a parameter; a name declared twice is a programming error (std::logic_error).
    ParamSpec& add(std::string name, ParamKind kind, std::string doc);
    /// Appends parameters shared by many types (every material's kr, kt, ...), tagged with `group`.
    TypeSpec& extend(const std::vector<ParamSpec>& shared, std::string_view group);

    const std::string& doc() const { return m_doc; }
    const std::vector<ParamSpec>& params() const { return m_params; }
    /// The declaration of `name`, or nullptr.
    const ParamSpec* find(std::string_view name) const;
    /// The declaration of `name` to change (a shared key's default for one type: glass's kr is 1); an
    /// undeclared name is a programming error (std::logic_error).
    ParamSpec& at(std::string_view name);
    std::vector<std::string> names() const;

private:
    std::string m_doc;
    std::vector<ParamSpec> m_params;
};

/// One line per parameter, as `--list --verbose` prints them:
/// "  name (colour or texture, default 0.8, in [0, 1] degrees): what it is". Parameters of a shared group
/// are left out when `with_groups` is false (a listing prints each group once).
std::string describe_params(const TypeSpec& spec, bool with_groups, std::string_view indent = "  ");
/// The same for one parameter, without the indent and the line end.
std::string describe_param(const ParamSpec& param);

}  // namespace rtlab

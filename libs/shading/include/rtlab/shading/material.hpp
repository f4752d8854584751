#pragma once
/// \brief Materials: a local reflection model plus the Whitted terms, created by name through a Registry.
#include <rtlab/core/color.hpp>
#include <rtlab/core/math.hpp>
#include <rtlab/core/registry.hpp>
#include <rtlab/shading/bsdf.hpp>
#include <rtlab/textures/texture.hpp>

#include <memory>
#include <optional>
#include <vector>

namespace rtlab {

/// \brief How light is measured and reflected: a scene picks one.
///
/// physical: BRDFs are normalised (Lambert albedo / pi), a point light of intensity I gives I / r^2.
/// classic:  the course's convention: Phong is kd (n.l) + ks (r.v)^e without pi, lights do not fall off
///           with distance, and an ambient light adds kd * ambient. Models that only exist physically based
///           (cook-torrance, ashikhmin-shirley) are scaled by pi, so their diffuse part matches kd (n.l).
enum class Convention { physical, classic };

/// \brief A material's values at one hit, its textures looked up once (per hit, not per light sample).
///
/// diffuse, specular and the two shape numbers mean what each model documents (Phong: kd, ks, exponent;
/// cook-torrance: kd, ks, roughness; ashikhmin-shirley: rd, rs, nu, nv). kr and kt are already limited as
/// the material documents (kr + kt <= 1 without Fresnel weighting, each <= 1 with it).
struct SurfaceTerms {
    RGB diffuse, specular;
    float shape_u = 0.0f, shape_v = 0.0f;
    RGB kr, kt;
    RGB emission;
    float opacity = 1.0f;
};

/// \brief A surface's response to light. Thread-safe: all methods are const and keep no state per call.
///
/// Every material carries the Whitted terms: kr (mirror reflection), kt (transmission), the indices of
/// refraction inside and outside (a hollow glass shell holds air: an inner surface with inside 1, outside
/// 1.5, or a reversed one), Fresnel weighting of kr and kt, an emission colour, an opacity (cut-outs; shadow
/// rays see it too; rtlab::opacity() of texture_param.hpp: a texture's alpha when it has one, else its
/// channel mean) and a Beer-Lambert absorption coefficient for the medium inside.
class Material {
public:
    /// The Whitted terms every material shares (textures are looked up in terms()).
    struct Whitted {
        std::shared_ptr<const Texture> kr, kt, emission, opacity;
        float ior_inside = 1.0f, ior_outside = 1.0f;
        bool fresnel = false;
        RGB absorption;  ///< per unit distance inside the medium; 0 = clear
        /// Under the sampling integrators emission leaves the front face only (outward normal) unless this is set.
        bool emission_two_sided = false;
    };

    explicit Material(Whitted whitted);
    virtual ~Material() = default;

    /// Every texture looked up for one hit. lookup.point is the object-space point, lookup.direction the
    /// ray's direction.
    SurfaceTerms terms(const TextureLookup& lookup) const {
        if (m_constant) return m_constant_terms;
        return looked_up_terms(lookup);
    }
    /// Whether terms() or shadow_transmittance() read their lookup: false when every term is a constant, so a
    /// caller may leave out what only textures need (a sphere's uv costs an atan2 and an acos per hit).
    bool reads_lookup() const { return !m_constant; }

    /// What multiplies the light arriving from wi (see Convention): f(wo, wi) cos(theta_i) when physical.
    /// wo and wi are unit vectors in the local shading frame (normal = +z), on the viewer's side; black when
    /// either is below the surface.
    virtual RGB direct(const SurfaceTerms& terms, const Vec3& wo, const Vec3& wi, Convention convention) const = 0;
    /// Whether direct() can be non-black: mirror and glass skip their lights and shadow rays.
    virtual bool reflects_direct_light() const { return true; }

    // Sampled scattering, always in the physical convention, for integrators that sample directions. The
    // directions are in the local shading frame as bsdf.hpp says: +z is the surface's outward normal, not
    // turned towards the viewer; opaque models answer for the side wo is on (two-sided), the Whitted
    // refraction and dielectric models tell the sides apart (ior_outside above, ior_inside below).
    //
    // The mixture. With a = opacity and, when fresnel is set, F the smooth interface's reflectance for wo
    // (n_wo_side / n_other_side; 1 under total internal reflection):
    //   R = kr F (kr without fresnel)        mirror reflection, a delta lobe
    //   T = kt (1 - F) (kt without fresnel)  refraction through the smooth interface, a delta lobe; under
    //                                        total internal reflection T is added to R
    //   B = max(0, 1 - R - T)                per channel: the model's own lobes get what the delta lobes leave
    //   whole: a (R + T + B f_model) + (1 - a) pass-through (wi = -wo, a delta transmission lobe: a cut-out)
    // Its albedo is a (R + T + B albedo_model) + 1 - a <= 1 whenever the model's own albedo is <= 1 (read_whitted
    // and terms() keep kr + kt <= 1 without fresnel, each <= 1 with it). sample() chooses one of the four in
    // proportion to the channel means of a B (0 for a model without sampled lobes), a R, a T and 1 - a; the
    // model's own sampler then picks among its parts. In radiance mode T is scaled by (n_wo / n_wi)^2.
    // Absorption inside (Beer-Lambert) and emission are the integrator's.

    /// f(wo, wi) of the whole mixture, without the cosine; delta lobes contribute nothing.
    RGB eval(const SurfaceTerms& terms, const Vec3& wo, const Vec3& wi, TransportMode mode) const;
    /// The solid-angle density with which sample() draws wi (delta lobes excluded).
    float pdf(const SurfaceTerms& terms, const Vec3& wo, const Vec3& wi, TransportMode mode) const;
    /// A direction from the mixture: uc in [0, 1) chooses the lobe (and is reused, rescaled, by the model to
    /// choose its part), u in [0, 1)^2 the direction. nullopt when the mixture is black or the draw is lost
    /// (a lobe that reaches below the horizon): the path ends there.
    std::optional<BsdfSample> sample(const SurfaceTerms& terms, const Vec3& wo, float uc, const Vec2& u,
                                     TransportMode mode) const;
    /// Whether sample() reads uc for these terms: false when the mixture is the model's own lobes alone and the
    /// model samples them without a choice (Lambert), so an integrator may leave that number undrawn.
    bool sample_uses_choice(const SurfaceTerms& terms) const;
    /// The probability that sample() draws from the model's own lobes (the part eval() and pdf() describe) rather
    /// than from a delta lobe, for this wo; 0 without sampled lobes. An integrator that estimates the non-delta part
    /// by other means (photon density) and follows the delta lobes by sampling weighs by it.
    float non_delta_chance(const SurfaceTerms& terms, const Vec3& wo) const;

    /// The fraction of light a shadow ray keeps crossing this surface: (1 - opacity) + opacity kt.
    RGB shadow_transmittance(const TextureLookup& lookup) const {
        if (m_constant_shadow) return m_shadow;
        return looked_up_shadow_transmittance(lookup);
    }
    /// Whether a shadow ray can cross this surface at all (kt not constant 0, or opacity not constant 1).
    bool transmits_shadows() const { return m_transmits; }

    float ior_inside() const { return m_whitted.ior_inside; }
    float ior_outside() const { return m_whitted.ior_outside; }
    bool fresnel() const { return m_whitted.fresnel; }
    const RGB& absorption() const { return m_whitted.absorption; }
    /// The emission texture (never null once constructed: read_whitted gives black), for the area lights.
    const std::shared_ptr<const Texture>& emission() const { return m_whitted.emission; }
    bool emission_two_sided() const { return m_whitted.emission_two_sided; }

protected:
    /// The model's own textures (diffuse, specular, shape numbers) for one hit.
    virtual void local_terms(const TextureLookup& lookup, SurfaceTerms& terms) const = 0;
    /// A model whose own terms are all constants calls this at the end of its constructor (where
    /// local_terms() is already its own): when the Whitted terms are constants too, terms() then returns
    /// one record worked out here, with no lookup and no virtual call per hit. A model that does not call it
    /// (a plugin's) keeps looking its terms up on every hit.
    void local_terms_are_constant();

    // The model's own lobes for the sampled interface (eval/pdf/sample above), in the physical convention and
    // without the Whitted terms, which Material adds. The default is "no sampled lobes": a plugin material
    // that only answers direct() scatters nothing but its Whitted terms under a sampling integrator (sampling
    // its direct() response, e.g. by cosine, would weigh light by a density that is not its own and so is
    // not physical). A model that samples overrides all four; unless lobes_transmit(), Material hands it
    // only pairs with wo.z > 0 and wi.z > 0, mirrored to the upper side when the viewer is below.
    virtual bool has_lobes() const { return false; }
    /// Whether the model's lobes reach through the surface (a dielectric): then it gets both sides as they are.
    virtual bool lobes_transmit() const { return false; }
    /// Whether lobe_sample() reads its uc (to choose among the model's parts); a model with one part may say no.
    virtual bool lobes_use_choice() const { return true; }
    virtual RGB lobe_eval(const SurfaceTerms&, const Vec3&, const Vec3&, TransportMode) const { return {}; }
    virtual float lobe_pdf(const SurfaceTerms&, const Vec3&, const Vec3&, TransportMode) const { return 0.0f; }
    virtual std::optional<LobeDraw> lobe_sample(const SurfaceTerms&, const Vec3&, float, const Vec2&,
                                                TransportMode) const {
        return std::nullopt;
    }

private:
    // The model's lobes on the side wo is on (two-sided opaque models), or as they are (transmitting ones).
    RGB own_eval(const SurfaceTerms& terms, Vec3 wo, Vec3 wi, TransportMode mode) const;
    float own_pdf(const SurfaceTerms& terms, Vec3 wo, Vec3 wi, TransportMode mode) const;
    std::optional<LobeDraw> own_sample(const SurfaceTerms& terms, Vec3 wo, float uc, const Vec2& u,
                                       TransportMode mode) const;

    /// A Whitted term with its value when constant, so constant terms cost no virtual call per hit.
    struct Term {
        const Texture* texture = nullptr;  // null when constant
        RGB value;
    };
    static Term make_term(const std::shared_ptr<const Texture>& texture, const RGB& fallback);
    static RGB term_value(const Term& term, const TextureLookup& lookup);
    float opacity(const TextureLookup& lookup) const;
    SurfaceTerms looked_up_terms(const TextureLookup& lookup) const;
    RGB looked_up_shadow_transmittance(const TextureLookup& lookup) const;

    Whitted m_whitted;
    Term m_kr, m_kt, m_emission, m_opacity;
    bool m_transmits = false;
    bool m_constant = false;         // terms() is m_constant_terms, whatever the lookup
    bool m_constant_shadow = false;  // shadow_transmittance() is m_shadow, whatever the lookup
    SurfaceTerms m_constant_terms;
    RGB m_shadow;
};

using MaterialRegistry = Registry<Material>;

/// Registers lambert, phong, blinn-phong, cook-torrance, ashikhmin-shirley, mirror, glass and rough-dielectric. Each
/// doc() lists the parameters; the Whitted parameters (kr, kt, ior, ior_outside, fresnel, emission, opacity,
/// absorption) are accepted by all.
void register_builtins(MaterialRegistry& registry);

/// A registry with category "material" and every built-in registered.
MaterialRegistry make_material_registry();

/// The keys every material shares (kr, kt, ior, ior_outside, fresnel, emission, opacity, absorption), declared
/// once: a material type, a plugin's too, declares them with `spec.extend(material_shared_params(), "material")`
/// and reads them with read_whitted(), so that a listing shows them once and every material takes them.
const std::vector<ParamSpec>& material_shared_params();

/// What a material type uses when a shared key is absent (glass: kr = kt = 1, ior 1.5, fresnel); a type whose
/// defaults differ says so in its declaration too (`spec.at("kr").defaults("1")`).
struct WhittedDefaults {
    RGB kr{0.0f}, kt{0.0f};
    float ior = 1.0f;
    bool fresnel = false;
};

/// Reads the shared keys of material_shared_params() into the Whitted terms, checked: colours >= 0, opacity in
/// [0, 1], indices > 0, constant kr + kt <= 1 without fresnel (each <= 1 with it). Throws rtlab::ParamError.
Material::Whitted read_whitted(const Params& params, const WhittedDefaults& defaults = {});

}  // namespace rtlab

// Loads the project's own module (from argv[1]) and the installed toon example (from argv[2], the install's
// plugin folder) by name, renders a sphere with a toon material coloured by the stripes texture, checks the
// pixels and writes the image to argv[3].
#include <rtlab/core/error.hpp>
#include <rtlab/core/image.hpp>
#include <rtlab/geometry/sphere.hpp>
#include <rtlab/render/render_job.hpp>
#include <rtlab/scene/plugin.hpp>

#include <cstdio>

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fputs("usage: rtlab_consumer_plugin_host MODULE_DIR INSTALLED_PLUGIN_DIR OUT.png\n", stderr);
        return 2;
    }
    try {
        rtlab::MaterialRegistry materials = rtlab::make_material_registry();
        rtlab::TextureRegistry textures = rtlab::make_texture_registry();
        rtlab::LightRegistry lights = rtlab::make_light_registry();
        rtlab::PluginHost host(materials, textures, lights, rtlab::plugin_search_path({argv[1], argv[2]}));
        host.load_by_name("stripes", "consumer");
        host.load_by_name("toon", "consumer");

        const rtlab::RGB red(0.9f, 0.1f, 0.1f), blue(0.1f, 0.1f, 0.9f), sky(0.2f, 0.8f, 0.3f);
        rtlab::Params stripe_params;
        stripe_params.set("a", rtlab::Params::List{red.r, red.g, red.b})
            .set("b", rtlab::Params::List{blue.r, blue.g, blue.b});
        const auto stripes = textures.create("stripes", stripe_params);
        // One band: every lit pixel is the texture's colour itself.
        rtlab::Params toon_params;
        toon_params.set_object<rtlab::Texture>("color", stripes).set("levels", 1.0);
        rtlab::RenderJob job;
        job.scene = std::make_shared<rtlab::Scene>(
            std::vector<rtlab::SceneObject>{{std::make_shared<rtlab::Sphere>(rtlab::Point3(0.0f), 1.0f),
                                             materials.create("toon", toon_params),
                                             {},
                                             "ball"}});
        job.camera = std::make_shared<rtlab::PinholeCamera>(rtlab::CameraSpec{
            .eye = {0, 0, 5}, .look_at = {0, 0, 0}, .vertical_fov_degrees = 30, .width = 96, .height = 96});
        rtlab::Params light_params;
        light_params.set("direction", rtlab::Params::List{0, 0, -1});
        job.lights = {lights.create("directional", light_params)};
        job.whitted.convention = rtlab::Convention::classic;
        job.whitted.background = sky;
        const rtlab::Image image = rtlab::render_job(job).image;
        rtlab::write_png(image, argv[3]);

        int n_red = 0, n_blue = 0, n_sky = 0, other = 0;
        for (int y = 0; y < image.height(); ++y) {
            for (int x = 0; x < image.width(); ++x) {
                const rtlab::RGB& c = image.at(x, y);
                n_red += c == red;
                n_blue += c == blue;
                n_sky += c == sky;
                other += !(c == red || c == blue || c == sky);
            }
        }
        std::printf("consumer plugin: %zu modules; red %d, blue %d, background %d, other %d pixels\n",
                    host.loaded().size(), n_red, n_blue, n_sky, other);
        // The sphere (radius 36.6 pixels) covers about 4200 of the 9216 pixels, in stripes of each colour.
        if (n_red < 1800 || n_blue < 1800 || n_sky < 4800 || n_sky > 5200 || other != 0) {
            std::puts("consumer plugin: unexpected image");
            return 1;
        }
        std::puts("consumer plugin: ok");
        return 0;
    } catch (const rtlab::Error& e) {
        std::fprintf(stderr, "consumer plugin: %s\n", e.what());
        return 1;
    }
}

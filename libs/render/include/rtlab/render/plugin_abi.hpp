#pragma once
/// \brief Forwards to the plugin boundary's home in the scene library, so that plugins written against
/// `rtlab/render/plugin_abi.hpp` keep building (they link rtlab::scene through rtlab_add_plugin).
#include <rtlab/scene/plugin_abi.hpp>

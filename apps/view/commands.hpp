#pragma once
// The commands that drive the viewer from a script or standard input (one per line, '#' starts a comment):
//   wait pass N | wait reloaded | wait error     hold the commands after it until that has happened
//   screenshot FILE.png                          save the whole window after the next frame ("saved FILE")
//   save FILE.{png,exr,hdr,pfm}                  the image: PNG as displayed, the others linear
//   orbit YAW PITCH (degrees) | pan RIGHT UP (view heights) | dolly FACTOR | reset | print-camera
//   tone none|reinhard|ward|aces | exposure STOPS | view image|variance|compare | reference FILE | zoom Z
//   inspect X Y                                  print the pixel's linear RGB and sample count
//   spp N | stats (frames per second, frame time, restart latency, rays/s) | quit
#include <optional>
#include <string>
#include <vector>

namespace rtlab::view {

struct Command {
    std::string name;
    std::vector<std::string> args;
};

/// Splits one line into a command; nothing for a blank or comment line. Throws rtlab::Error naming `where`
/// (FILE:LINE or "stdin") for an unknown command or a wrong number of arguments.
std::optional<Command> parse_command(const std::string& line, const std::string& where);

}  // namespace rtlab::view

// `cetview view --script FILE`: simple commands that drive the window without a person (tests,
// demos). One command per line; '#' starts a comment. The viewer runs one command per frame and
// waits where a command says so (a camera transition in progress also holds the script).
//
//   deflection 0.05% | deflection 0.2     chordal deflection slider (relative or absolute)
//   angle 12                              angular deflection slider, degrees
//   view iso|front|back|left|right|top|bottom
//   projection perspective|orthographic
//   display shaded|shaded-edges|wireframe
//   colors on|off      heatmap on|off     fit
//   panel tessellation|progress|display|model|stats on|off
//   orbit DX DY        pan DX DY          zoom STEPS      (pixels / wheel steps, at the window centre)
//   wait level K|target                   until level K (or the slider's level) is complete and shown
//   wait frames N
//   wait seconds S                        S seconds, drawing only what changes (as when nobody scripts)
//   screenshot FILE.png                   quit
//   open FILE                             starts loading FILE; the next command (but cancel and
//                                         wait frames|seconds) waits until it has opened or failed
//   cancel                                cancels the load in progress (the current model stays)
//   browse DIR                            shows the File > Open dialog listing DIR
#pragma once

#include <string>
#include <vector>

namespace cetview {

struct ScriptCommand {
  std::string name;               // first word
  std::vector<std::string> args;  // the rest, split at whitespace
  int line = 0;                   // 1-based, for messages
};

struct ScriptParse {
  std::vector<ScriptCommand> commands;
  std::string error;  // one line ("FILE:LINE: ..."), empty on success
};

// Checks every command's name and argument count (not the values, which the viewer checks when it
// runs them with the same parsers as its command line).
ScriptParse parseScript(const std::string& text, const std::string& fileName);
ScriptParse loadScript(const std::string& path);

}  // namespace cetview

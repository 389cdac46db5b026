#include "open_dialog.h"

#include <imgui.h>

#include <cstring>
#include <filesystem>

namespace cetview {

namespace {
constexpr const char* kTitle = "Open model";

void copyPath(char* to, std::size_t size, const std::string& from) {
  std::strncpy(to, from.c_str(), size - 1);
  to[size - 1] = '\0';
}
}  // namespace

void OpenDialog::open(const std::string& directory) {
  list(directory);
  opening_ = true;
}

void OpenDialog::list(const std::string& directory) {
  listing_ = listModelDirectory(directory);
  selected_ = -1;
  copyPath(path_, sizeof path_, listing_.directory + "/");
}

std::optional<std::string> OpenDialog::draw() {
  namespace fs = std::filesystem;
  if (opening_) {
    ImGui::OpenPopup(kTitle);
    opening_ = false;
  }
  std::optional<std::string> chosen;
  ImGui::SetNextWindowSize(ImVec2(620.0f, 440.0f), ImGuiCond_Appearing);
  if (!ImGui::BeginPopupModal(kTitle, nullptr)) return chosen;
  ImGui::TextWrapped("%s", listing_.directory.c_str());
  std::string enter;  // a directory to list once the loop over the entries is done
  if (ImGui::Button("Up")) enter = fs::path(listing_.directory).parent_path().string();
  ImGui::SameLine();
  ImGui::TextDisabled("STEP, IGES and .brep files; or drop one onto the window");
  ImGui::BeginChild("##entries", ImVec2(0.0f, -2.0f * ImGui::GetFrameHeightWithSpacing()), true);
  if (!listing_.error.empty()) ImGui::TextWrapped("%s", listing_.error.c_str());
  if (listing_.error.empty() && listing_.entries.empty())
    ImGui::TextDisabled("no model files or folders here");
  const float sizeColumn = ImGui::GetWindowContentRegionMax().x - 90.0f;
  // Only the rows in view are laid out: a folder may hold thousands of files.
  ImGuiListClipper clipper;
  clipper.Begin(static_cast<int>(listing_.entries.size()));
  while (clipper.Step()) {
    for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
      const BrowserEntry& e = listing_.entries[static_cast<std::size_t>(i)];
      const std::string full = (fs::path(listing_.directory) / e.name).string();
      const std::string label = e.directory ? e.name + "/" : e.name;
      ImGui::PushID(i);
      if (ImGui::Selectable(label.c_str(), selected_ == i, ImGuiSelectableFlags_AllowDoubleClick)) {
        selected_ = i;
        if (e.directory) {
          if (ImGui::IsMouseDoubleClicked(0)) enter = full;
        } else {
          copyPath(path_, sizeof path_, full);
          if (ImGui::IsMouseDoubleClicked(0)) chosen = full;
        }
      }
      if (!e.directory) {
        ImGui::SameLine(sizeColumn);
        ImGui::TextDisabled("%s", humanBytes(e.bytes).c_str());
      }
      ImGui::PopID();
    }
  }
  ImGui::EndChild();
  ImGui::SetNextItemWidth(-150.0f);
  const bool typed = ImGui::InputText("##path", path_, sizeof path_, ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  const bool openPressed = ImGui::Button("Open");
  ImGui::SameLine();
  bool close = ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false);
  if ((typed || openPressed) && path_[0] != '\0') {
    std::error_code ec;
    if (fs::is_directory(path_, ec)) {
      enter = path_;  // a typed folder is listed, not opened
    } else {
      chosen = std::string(path_);
    }
  }
  if (!enter.empty()) list(enter);
  if (chosen) close = true;
  if (close) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
  return chosen;
}

}  // namespace cetview

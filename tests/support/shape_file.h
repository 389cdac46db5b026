// OpenCASCADE shapes through cetview's public loader, which takes a path: the shape is written to a
// .brep file, loaded, and the file removed. Shared by the brep tests and the face fuzz target.
#pragma once

#include <unistd.h>

#include <string>

#include <BRepTools.hxx>
#include <TopoDS_Shape.hxx>

#include "brep/model.h"

namespace cetview::test {

// Writes `shape` to `path` (which should be private to this process) and loads it with
// brep::loadModel; a write failure is returned as the load error.
inline brep::LoadResult loadShapeThroughFile(const TopoDS_Shape& shape, const std::string& path) {
  brep::LoadResult r;
  if (!BRepTools::Write(shape, path.c_str())) {
    r.error = "cannot write " + path;
    return r;
  }
  r = brep::loadModel(path);
  ::unlink(path.c_str());
  return r;
}

}  // namespace cetview::test

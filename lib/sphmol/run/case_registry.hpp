#pragma once
// Case name -> factory, per dimension. A case that exists only in some dimensions returns nullptr
// from its factory in the others, and the run reports that with the case's reason.
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "sphmol/run/case.hpp"

namespace sphmol {

struct CaseFactory {
  std::function<std::unique_ptr<Case<1>>()> d1;
  std::function<std::unique_ptr<Case<2>>()> d2;
  std::function<std::unique_ptr<Case<3>>()> d3;
  std::string dimensions_note;  // e.g. "two-dimensional only"
};

// All registered cases. Adding a case: write scenes/<name>_case.cpp and add it in case_registry.cpp.
const std::map<std::string, CaseFactory>& case_registry();

}  // namespace sphmol

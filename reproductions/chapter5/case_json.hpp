// A Chapter 5 case's record and a back-calculation's result as JSON, the form in which an
// ensemble member hands them back (issue 33: members on threads or MPI ranks, results cached on
// disk by their key). Every double reads back bit for bit: finite numbers as JSON numbers
// (nlohmann::json writes enough digits to round-trip), NaN and infinities as the strings "nan",
// "-nan", "inf", "-inf" (a NaN keeps its sign, which printf shows). So a value measured from a
// case read back is the value measured from the case as it ran, wherever it ran.
#pragma once
#include <nlohmann/json.hpp>

#include "chapter5/backcalc.hpp"
#include "chapter5/ch5.hpp"

namespace kolsky::ch5 {

nlohmann::json to_json(const CaseSpec& spec);
CaseSpec spec_from_json(const nlohmann::json& j);

nlohmann::json to_json(const CaseResult& c);
CaseResult case_from_json(const nlohmann::json& j);

nlohmann::json to_json(const BackCalcResult& r);
BackCalcResult backcalc_from_json(const nlohmann::json& j);

}  // namespace kolsky::ch5

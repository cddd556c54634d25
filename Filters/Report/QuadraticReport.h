// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_report_QuadraticReport_h
#define labelmesher_report_QuadraticReport_h

/**
 * @file QuadraticReport.h
 * The quadratic mesh's part of the run report (RunReport::Quadratic): its text
 * summary and its JSON object. AddQuadratic and QuadraticHolds are declared
 * in RunReport.h.
 */

#include "RunReport.h"

#include <ostream>

namespace labelmesher
{
namespace report
{

/// Nothing when the report has no quadratic mesh.
void PrintQuadraticSummary(const RunReport& report, std::ostream& out);
/// The report's "quadratic" value: an object, or null.
void WriteQuadraticJson(const RunReport& report, JsonWriter& json);

} // namespace report
} // namespace labelmesher

#endif

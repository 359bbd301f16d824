// SPDX-License-Identifier: MIT
#include "metricspec.h"

#include "perceivingoperator.h"
#include "simrun.h"
#include "tasktype.h"

namespace semhap {

const std::vector<MetricSpec> &MetricSpec::all()
{
    static const std::vector<MetricSpec> table = [] {
        std::vector<MetricSpec> rows;
        const auto add = [&rows](const std::vector<MetricSpec> &specs) {
            rows.insert(rows.end(), specs.begin(), specs.end());
        };
        for (const TaskType &type : TaskType::all())
            add(type.metrics());
        add(PerceivingOperator::metricSpecs());
        add(SimRun::metricSpecs());
        return rows;
    }();
    return table;
}

const MetricSpec *MetricSpec::find(const QString &name)
{
    for (const MetricSpec &spec : all()) {
        if (name == QLatin1String(spec.name))
            return &spec;
    }
    return nullptr;
}

std::vector<const MetricSpec *> MetricSpec::numbers(MetricRole role)
{
    std::vector<const MetricSpec *> out;
    for (const MetricSpec &spec : all()) {
        if (spec.role == role && spec.unit != MetricUnit::Text)
            out.push_back(&spec);
    }
    return out;
}

} // namespace semhap

// SPDX-License-Identifier: MIT
#pragma once

#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <QStringList>

#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace semhap {

/** The named live parameters of a pattern, each with its index and default value. */
class ParamTable
{
public:
    ParamTable(); ///< holds `intensity` (index 0, default 1) and nothing else

    /** Adds a parameter or changes its default; returns its index. */
    int declare(const QString &name, double defaultValue);
    int indexOf(const QString &name) const; ///< -1 when unknown
    int size() const { return int(m_names.size()); }
    const QString &name(int index) const { return m_names[size_t(index)]; }
    double defaultValue(int index) const { return m_defaults[size_t(index)]; }
    const std::vector<double> &defaults() const { return m_defaults; }

    static constexpr int Intensity = 0;

private:
    std::vector<QString> m_names;
    std::vector<double> m_defaults;
};

/** A mapping from a live parameter's value to a number: identity, linear, or points. */
class Curve
{
public:
    Curve() = default; ///< identity
    static Curve linear(double gain, double offset);
    /** Piecewise linear through points sorted by x, held constant outside them. */
    static Curve points(std::vector<std::pair<double, double>> points);

    double map(double x) const;
    bool isIdentity() const { return m_kind == Kind::Identity; }

    enum class Kind
    {
        Identity,
        Linear,
        Points
    };
    Kind kind() const { return m_kind; }
    double gain() const { return m_gain; }
    double offset() const { return m_offset; }
    const std::vector<std::pair<double, double>> &pointList() const { return m_points; }

private:
    Kind m_kind = Kind::Identity;
    double m_gain = 1.0;
    double m_offset = 0.0;
    std::vector<std::pair<double, double>> m_points;
};

/**
 * A numeric parameter of a waveform: a constant, or a live parameter through a curve.
 * JSON: `1.5`, `{"param": "intensity"}`, `{"param": "intensity", "gain": 18, "offset": 2}`
 * or `{"param": "intensity", "curve": [[0, 2], [1, 20]]}`.
 */
class Number
{
public:
    Number(double constant = 0.0) : m_constant(constant) {} // NOLINT: numbers convert
    static Number bound(int param, Curve curve);

    double value(const double *params) const
    {
        return m_param < 0 ? m_constant : m_curve.map(params[m_param]);
    }
    bool isConstant() const { return m_param < 0; }
    int param() const { return m_param; }
    const Curve &curve() const { return m_curve; }
    /** The JSON form the waveform parser reads back (a number or a `{"param": …}` object). */
    QJsonValue toJson(const ParamTable &params) const;

private:
    double m_constant = 0.0;
    int m_param = -1;
    Curve m_curve;
};

/**
 * A Number as its JSON writes it, read without a pattern's parameter table: what an editor
 * shows and changes of a binding. The waveform parser checks the same JSON strictly; this
 * reads what is there and writes it back in its shortest form.
 */
struct NumberJson
{
    double constant = 0.0;
    QString param; ///< empty: a constant
    double gain = 1.0;
    double offset = 0.0;
    /** The `curve` points as written; undefined: gain and offset apply. */
    QJsonValue curve{QJsonValue::Undefined};

    bool isBound() const { return !param.isEmpty(); }
    /** Reads `json`: a number, or a `{"param": …}` object. */
    static NumberJson read(const QJsonValue &json);
    /** A number, or `{"param"}` with its `curve`, else `gain` and `offset` unless 1 and 0. */
    QJsonValue toJson() const;
};

/** Writes `number` under `key` unless it is the constant `defaultValue`, keeping files short. */
void insertNumber(QJsonObject &object, const QString &key, const Number &number,
                  const ParamTable &params, double defaultValue);

/** Everything a waveform needs to produce one sample. */
struct WaveformContext
{
    double t = 0.0;                 ///< seconds since this waveform started
    double dt = 0.0;                ///< seconds since the previous sample, 0 on the first
    double from = 0.0;              ///< the track's value when this waveform started
    double peak = 0.0;              ///< the track's highest value from the last begin
                                    ///< to the start of this waveform
    const double *params = nullptr; ///< live parameter values, indexed as the ParamTable
    double *state = nullptr;        ///< the voice's state slots for the whole waveform tree
};

/**
 * A waveform as a value: samples `value(t)` from a context. Waveforms are immutable and
 * shared; whatever changes while one plays (oscillator phase, the current step of a
 * sequence) lives in the voice's state slots, so sampling never allocates.
 */
class Waveform
{
public:
    virtual ~Waveform() = default;

    /** The type name used in JSON (`"const"`, `"ramp"`, …). */
    virtual QString type() const = 0;
    /** One sample at ctx.t; advances the state by ctx.dt. */
    virtual double sample(const WaveformContext &ctx) const = 0;
    /** Puts this node's state (and its children's) back to the start of the waveform. */
    virtual void reset(double *state) const;
    /** Length in seconds under the given parameters; infinity for waveforms that never end. */
    virtual double duration(const double *params) const;
    /** Serialises to the JSON form the parser reads. */
    virtual QJsonValue toJson(const ParamTable &params) const = 0;

    /** Gives this node (and, in composites, its children) state slots from `next` on. */
    virtual void assignState(int &next);
    int stateOffset() const { return m_stateOffset; }

    static constexpr double Forever = std::numeric_limits<double>::infinity();
    /**
     * Seconds within which an edge (a segment's end, a square edge, a pulse's width) counts
     * as reached, so that the rounding of sample times like k/1000 never adds or drops a
     * sample at an edge that falls exactly on one.
     */
    static constexpr double TimeTolerance = 1e-9;

protected:
    /** How many state slots this node needs for itself (children not counted). */
    virtual int ownStateSize() const { return 0; }
    int m_stateOffset = 0;
};

using WaveformPtr = std::unique_ptr<Waveform>;

} // namespace semhap

// Template part of bind.hpp: the parameter classes, one per schema table.
#include <memory>

#include "core/common/json.hpp"

namespace lwb::py {

template <class P>
py::object fieldValue(const core::Schema<P>& s, const typename core::Schema<P>::Field& f, const P& p) {
    switch (f.kind) {
        case core::FieldKind::Text: return py::str(f.getText(p));
        case core::FieldKind::Boolean: return py::bool_(f.get(p) != 0);
        case core::FieldKind::Choice: return py::str(s.valueText(f, p));
        case core::FieldKind::Integer: return py::int_(static_cast<long long>(std::llround(f.get(p))));
        case core::FieldKind::Range: {
            const core::RangeValue r = f.getRange(p);
            if (!r.enabled) return py::none();
            return py::make_tuple(r.lo, r.hi);
        }
        case core::FieldKind::Real: {
            const double v = f.get(p);
            if (std::isnan(v)) return py::none();
            return py::float_(v);
        }
    }
    return py::none();
}

template <class P>
void applyDict(const core::Schema<P>& s, const py::dict& d, P* p, void (*afterSet)(P*, const std::string&)) {
    for (const auto& kv : d) {
        const std::string key = py::str(kv.first);
        std::string err;
        if (!s.setFromText(p, key, valueText(kv.second), &err)) throw ParameterError(err);
        if (afterSet) afterSet(p, key);
    }
}

template <class P>
P paramsFrom(const py::object& params, const ParamsBinding<P>& b) {
    if (params.is_none()) return b.defaults();
    if (py::isinstance<P>(params)) return params.cast<P>();
    if (py::isinstance<py::dict>(params)) {
        P p = b.defaults();
        applyDict(b.schema(), params.cast<py::dict>(), &p, b.afterSet);
        if (const std::string e = b.familyCheck(p); !e.empty()) throw ParameterError(e);
        return p;
    }
    throw py::type_error(std::string("params must be None, a dict {key: value} or laserwb.") + b.name);
}

template <class P>
py::class_<P> bindParams(py::module_& m, const ParamsBinding<P>& b) {
    // The docstring: the summary and the schema's own table (kept for the module's lifetime).
    auto* doc = new std::string(std::string(b.summary) + "\n\nP[key] reads a parameter, P[key] = value sets it with the " +
                                "same rules and messages as the CLI's --set KEY=VALUE (laserwb.ParameterError).\n" +
                                "Parameters (key = default unit  valid range, then the meaning):\n" +
                                b.schema().describe(b.defaults()));
    py::class_<P> c(m, b.name, doc->c_str());
    const ParamsBinding<P> bb = b;
    c.def(py::init([bb](const py::object& values) {
              P p = bb.defaults();
              if (!values.is_none()) applyDict(bb.schema(), values.cast<py::dict>(), &p, bb.afterSet);
              return p;
          }),
          py::arg("values") = py::none(), "The command's defaults, with `values` ({key: value}) set over them.");
    c.def("__getitem__", [bb](const P& p, const std::string& key) {
        const auto* f = bb.schema().find(key);
        if (!f) throw py::key_error("unknown parameter \"" + key + "\" for " + bb.schema().name());
        return fieldValue(bb.schema(), *f, p);
    });
    c.def("__setitem__", [bb](P& p, const std::string& key, const py::handle& v) {
        std::string err;
        if (!bb.schema().setFromText(&p, key, valueText(v), &err)) throw ParameterError(err);
        if (bb.afterSet) bb.afterSet(&p, key);
    });
    c.def("__contains__", [bb](const P&, const std::string& key) { return bb.schema().find(key) != nullptr; });
    c.def("__len__", [bb](const P&) { return bb.schema().fields().size(); });
    c.def("__iter__", [bb](const P&) {
        py::list keys;
        for (const auto& f : bb.schema().fields()) keys.append(f.key);
        return py::iter(keys);
    });
    c.def("keys", [bb](const P&) {
        std::vector<std::string> keys;
        for (const auto& f : bb.schema().fields()) keys.push_back(f.key);
        return keys;
    }, "Every key, in the schema's order.");
    c.def("to_dict", [bb](const P& p) {
        py::dict d;
        for (const auto& f : bb.schema().fields()) d[py::str(f.key)] = fieldValue(bb.schema(), f, p);
        return d;
    }, "{key: value} of every parameter.");
    c.def("update", [bb](P& p, const py::dict& d) { applyDict(bb.schema(), d, &p, bb.afterSet); },
          "Sets every key of the dict, as p[key] = value does.");
    c.def("to_json", [bb](const P& p) { return core::dumpJson(bb.schema().toJson(p)); },
          "The parameters as JSON, as `laserwb-cli ... --print-config` writes them.");
    c.def("load", [bb](P& p, const std::string& path) {
        const core::JsonParseResult j = core::readJsonFile(path);
        if (!j.ok) throw ParameterError(j.error);
        std::string err;
        const bool ok = bb.fromJson ? bb.fromJson(j, &p, &err) : bb.schema().fromJson(j.value, &p, &err, &j);
        if (!ok) throw ParameterError(err);
    }, py::arg("path"), "Reads a config file over these parameters, as --config does (FILE:LINE:COL in errors).");
    c.def("validate", [bb](const P& p) {
        std::string e = bb.schema().validate(p);
        if (e.empty()) e = bb.familyCheck(p);
        if (!e.empty()) throw ParameterError(e);
    }, "Raises laserwb.ParameterError with the schema's message when a value or a rule between values is wrong.");
    c.def("describe", [bb](const P& p, const std::string& key) {
        const auto* f = bb.schema().find(key);
        if (!f) throw py::key_error("unknown parameter \"" + key + "\" for " + bb.schema().name());
        py::dict d;
        d["key"] = f->key;
        d["unit"] = f->unit;
        d["range"] = f->rangeText();
        d["doc"] = f->doc;
        d["default"] = fieldValue(bb.schema(), *f, bb.defaults());
        d["value"] = fieldValue(bb.schema(), *f, p);
        if (!f->choices.empty()) d["choices"] = f->choices;
        return d;
    }, py::arg("key"), "The schema row of `key`: unit, valid range, doc, default and the value here.");
    // laserwb.FAMILY.NAME(...): eval() gives it back; "# defaults" when nothing differs.
    std::string family = py::str(m.attr("__name__"));
    family = "laserwb." + family.substr(family.rfind('.') + 1) + "." + bb.name;
    c.def("__repr__", [bb, family](const P& p) {
        std::string s = family + "({";
        bool first = true;
        const P d = bb.defaults();
        for (const auto& f : bb.schema().fields()) {
            const std::string v = bb.schema().valueText(f, p);
            if (v == bb.schema().valueText(f, d)) continue;
            s += (first ? "'" : ", '") + f.key + "': " + std::string(py::str(py::repr(fieldValue(bb.schema(), f, p))));
            first = false;
        }
        return first ? family + "()  # defaults" : s + "})";
    });
    c.def("__eq__", [bb](const P& a, const P& b2) { return bb.schema().changedKeys(a, b2).empty(); });
    c.def("copy", [](const P& p) { return P(p); });
    c.def(py::pickle([bb](const P& p) { return core::dumpJson(bb.schema().toJson(p)); },
                     [bb](const std::string& json) {
                         P p = bb.defaults();
                         const core::JsonParseResult j = core::parseJson(json, "pickle");
                         std::string err;
                         if (!j.ok || !bb.schema().fromJson(j.value, &p, &err, &j)) throw ParameterError(j.ok ? err : j.error);
                         return p;
                     }));
    return c;
}

}  // namespace lwb::py

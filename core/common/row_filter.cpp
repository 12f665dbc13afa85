#include "core/common/row_filter.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>

#include "core/common/text.hpp"

namespace lwb::core {

FilterCell FilterCell::str(std::string s) {
    FilterCell c;
    double v;
    if (parseDouble(trim(s), &v)) c.number = v;
    c.text = std::move(s);
    c.isText = true;
    return c;
}

enum class NodeKind : uint8_t { Number, Text, Column, Neg, Add, Sub, Mul, Div, Abs, Sqrt, Cmp, And, Or, Not };
enum class CmpOp : uint8_t { Lt, Le, Gt, Ge, Eq, Ne };

struct RowFilterNode {
    NodeKind kind = NodeKind::Number;
    CmpOp op = CmpOp::Eq;
    int a = -1, b = -1;  // children
    int column = -1;
    double number = 0;
    std::string text;    // a text literal, lower case
};

namespace {

enum class Tok { Number, String, Ident, LParen, RParen, Op, And, Or, Not, End };

struct Token {
    Tok kind = Tok::End;
    std::string text;  // as written (a string: its content)
    double number = 0;
    size_t pos = 0;    // 0-based
};

// Node values: a boolean (comparisons, and/or/not) or a value (number or text).
enum class Type { Bool, Value };

struct Value {
    double number = std::numeric_limits<double>::quiet_NaN();
    const std::string* text = nullptr;  // set for a text (lower case when a literal)
    bool literal = false;               // text is already lower case
};

std::string at(size_t pos0) { return " at " + std::to_string(pos0 + 1); }

std::string describe(const Token& t) {
    switch (t.kind) {
        case Tok::End: return "the end";
        case Tok::String: return "\"" + t.text + "\"";
        default: return "'" + t.text + "'";
    }
}

bool lex(const std::string& s, std::vector<Token>* out, std::string* error, size_t* errorPos) {
    size_t i = 0;
    auto fail = [&](size_t pos, const std::string& what) {
        *error = what + at(pos);
        *errorPos = pos + 1;
        return false;
    };
    while (i < s.size()) {
        const char c = s[i];
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
            ++i;
            continue;
        }
        Token t;
        t.pos = i;
        if ((c >= '0' && c <= '9') || (c == '.' && i + 1 < s.size() && s[i + 1] >= '0' && s[i + 1] <= '9')) {
            size_t j = i;
            while (j < s.size() && ((s[j] >= '0' && s[j] <= '9') || s[j] == '.')) ++j;
            if (j < s.size() && (s[j] == 'e' || s[j] == 'E')) {
                size_t k = j + 1;
                if (k < s.size() && (s[k] == '+' || s[k] == '-')) ++k;
                if (k < s.size() && s[k] >= '0' && s[k] <= '9') {
                    while (k < s.size() && s[k] >= '0' && s[k] <= '9') ++k;
                    j = k;
                }
            }
            t.text = s.substr(i, j - i);
            if (!parseDouble(t.text, &t.number)) return fail(i, "number '" + t.text + "' malformed");
            if (j < s.size() && (std::isalpha(static_cast<unsigned char>(s[j])) || s[j] == '_'))
                return fail(j, "expected an operator or a space after the number '" + t.text + "'");
            t.kind = Tok::Number;
            i = j;
        } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
            size_t j = i;
            while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '_')) ++j;
            t.text = s.substr(i, j - i);
            const std::string low = toLower(t.text);
            t.kind = low == "and" ? Tok::And : low == "or" ? Tok::Or : low == "not" ? Tok::Not : Tok::Ident;
            i = j;
        } else if (c == '"' || c == '\'') {
            size_t j = i + 1;
            std::string content;
            while (j < s.size() && s[j] != c) {
                if (s[j] == '\\' && j + 1 < s.size()) ++j;  // \" and \\ inside a string
                content += s[j++];
            }
            if (j >= s.size()) return fail(i, std::string("string not closed (no ") + c + " after it) starting");
            t.kind = Tok::String;
            t.text = content;
            i = j + 1;
        } else if (c == '(' || c == ')') {
            t.kind = c == '(' ? Tok::LParen : Tok::RParen;
            t.text = std::string(1, c);
            ++i;
        } else {
            const std::string two = s.substr(i, 2);
            if (two == "<=" || two == ">=" || two == "==" || two == "!=") {
                t.kind = Tok::Op;
                t.text = two;
                i += 2;
            } else if (two == "&&" || two == "||") {
                t.kind = two == "&&" ? Tok::And : Tok::Or;
                t.text = two;
                i += 2;
            } else if (c == '<' || c == '>' || c == '+' || c == '-' || c == '*' || c == '/') {
                t.kind = Tok::Op;
                t.text = std::string(1, c);
                ++i;
            } else if (c == '!') {
                t.kind = Tok::Not;
                t.text = "!";
                ++i;
            } else if (c == '=') {
                return fail(i, "expected '==' (one '=' is no comparison)");
            } else {
                return fail(i, "unexpected character '" + std::string(1, c) + "'");
            }
        }
        out->push_back(t);
    }
    Token end;
    end.pos = s.size();
    out->push_back(end);
    return true;
}

}  // namespace

// Recursive descent over the tokens; builds the node list (children before parents).
struct RowFilterCompiler {
    const RowFilterParams& params;
    std::vector<Token> toks;
    size_t k = 0;
    RowFilter* out = nullptr;
    std::string error;
    size_t errorPos = 0;
    int depth = 0;
    std::vector<std::string> lowColumns;

    const Token& peek() const { return toks[k]; }
    bool failAt(const Token& t, const std::string& what) {
        if (error.empty()) {
            error = what + at(t.pos);
            errorPos = t.pos + 1;
        }
        return false;
    }
    int add(RowFilterNode n) {
        out->m_nodes.push_back(std::move(n));
        return int(out->m_nodes.size()) - 1;
    }
    std::string columnList() const {
        std::string l;
        for (size_t i = 0; i < params.columns.size(); ++i) l += (i ? ", " : "") + params.columns[i];
        return l;
    }

    // expr := and ('or' and)*
    bool parseOr(int* node, Type* type) {
        if (++depth > 200) return failAt(peek(), "expression nested too deeply");
        const Token first = peek();
        if (!parseAnd(node, type)) return false;
        while (peek().kind == Tok::Or) {
            const Token op = toks[k++];
            if (*type != Type::Bool) return failAt(first, "expected a comparison before '" + op.text + "'");
            int rhs;
            Type rt;
            const Token rfirst = peek();
            if (!parseAnd(&rhs, &rt)) return false;
            if (rt != Type::Bool) return failAt(rfirst, "expected a comparison after '" + op.text + "'");
            RowFilterNode n;
            n.kind = NodeKind::Or;
            n.a = *node;
            n.b = rhs;
            *node = add(n);
        }
        --depth;
        return true;
    }
    bool parseAnd(int* node, Type* type) {
        const Token first = peek();
        if (!parseNot(node, type)) return false;
        while (peek().kind == Tok::And) {
            const Token op = toks[k++];
            if (*type != Type::Bool) return failAt(first, "expected a comparison before '" + op.text + "'");
            int rhs;
            Type rt;
            const Token rfirst = peek();
            if (!parseNot(&rhs, &rt)) return false;
            if (rt != Type::Bool) return failAt(rfirst, "expected a comparison after '" + op.text + "'");
            RowFilterNode n;
            n.kind = NodeKind::And;
            n.a = *node;
            n.b = rhs;
            *node = add(n);
        }
        return true;
    }
    bool parseNot(int* node, Type* type) {
        if (peek().kind == Tok::Not) {
            const Token op = toks[k++];
            if (++depth > 200) return failAt(op, "expression nested too deeply");
            const Token first = peek();
            int a;
            Type t;
            if (!parseNot(&a, &t)) return false;
            --depth;
            if (t != Type::Bool) return failAt(first, "expected a comparison after '" + op.text + "'");
            RowFilterNode n;
            n.kind = NodeKind::Not;
            n.a = a;
            *node = add(n);
            *type = Type::Bool;
            return true;
        }
        return parseCmp(node, type);
    }
    bool parseCmp(int* node, Type* type) {
        const Token first = peek();
        if (!parseSum(node, type)) return false;
        const Token& t = peek();
        static const char* ops[] = {"<", "<=", ">", ">=", "==", "!="};
        int op = -1;
        if (t.kind == Tok::Op)
            for (int i = 0; i < 6; ++i)
                if (t.text == ops[i]) op = i;
        if (op < 0) return true;
        const Token opTok = toks[k++];
        if (*type != Type::Value) return failAt(first, "expected a value before '" + opTok.text + "'");
        int rhs;
        Type rt;
        const Token rfirst = peek();
        if (!parseSum(&rhs, &rt)) return false;
        if (rt != Type::Value) return failAt(rfirst, "expected a value after '" + opTok.text + "'");
        if (peek().kind == Tok::Op)
            for (const char* o : ops)
                if (peek().text == o)
                    return failAt(peek(), "expected 'and' or 'or' between comparisons, not '" + peek().text + "'");
        RowFilterNode n;
        n.kind = NodeKind::Cmp;
        n.op = CmpOp(op);
        n.a = *node;
        n.b = rhs;
        *node = add(n);
        *type = Type::Bool;
        return true;
    }
    bool parseSum(int* node, Type* type) {
        if (!parseProduct(node, type)) return false;
        while (peek().kind == Tok::Op && (peek().text == "+" || peek().text == "-")) {
            const Token op = toks[k++];
            if (*type != Type::Value) return failAt(op, "expected a value before '" + op.text + "'");
            int rhs;
            Type rt;
            const Token rfirst = peek();
            if (!parseProduct(&rhs, &rt)) return false;
            if (rt != Type::Value) return failAt(rfirst, "expected a value after '" + op.text + "'");
            RowFilterNode n;
            n.kind = op.text == "+" ? NodeKind::Add : NodeKind::Sub;
            n.a = *node;
            n.b = rhs;
            *node = add(n);
        }
        return true;
    }
    bool parseProduct(int* node, Type* type) {
        if (!parseUnary(node, type)) return false;
        while (peek().kind == Tok::Op && (peek().text == "*" || peek().text == "/")) {
            const Token op = toks[k++];
            if (*type != Type::Value) return failAt(op, "expected a value before '" + op.text + "'");
            int rhs;
            Type rt;
            const Token rfirst = peek();
            if (!parseUnary(&rhs, &rt)) return false;
            if (rt != Type::Value) return failAt(rfirst, "expected a value after '" + op.text + "'");
            RowFilterNode n;
            n.kind = op.text == "*" ? NodeKind::Mul : NodeKind::Div;
            n.a = *node;
            n.b = rhs;
            *node = add(n);
        }
        return true;
    }
    bool parseUnary(int* node, Type* type) {
        if (peek().kind == Tok::Op && (peek().text == "-" || peek().text == "+")) {
            const Token op = toks[k++];
            if (++depth > 200) return failAt(op, "expression nested too deeply");
            const Token first = peek();
            int a;
            if (!parseUnary(&a, type)) return false;
            --depth;
            if (*type != Type::Value) return failAt(first, "expected a value after '" + op.text + "'");
            if (op.text == "+") {
                *node = a;
                return true;
            }
            RowFilterNode n;
            n.kind = NodeKind::Neg;
            n.a = a;
            *node = add(n);
            return true;
        }
        return parsePrimary(node, type);
    }
    bool parsePrimary(int* node, Type* type) {
        const Token t = peek();
        RowFilterNode n;
        switch (t.kind) {
            case Tok::Number:
                ++k;
                n.kind = NodeKind::Number;
                n.number = t.number;
                *node = add(n);
                *type = Type::Value;
                return true;
            case Tok::String:
                ++k;
                n.kind = NodeKind::Text;
                n.text = toLower(t.text);
                if (!parseDouble(trim(t.text), &n.number)) n.number = std::numeric_limits<double>::quiet_NaN();
                *node = add(n);
                *type = Type::Value;
                return true;
            case Tok::LParen: {
                ++k;
                if (!parseOr(node, type)) return false;
                if (peek().kind != Tok::RParen)
                    return failAt(peek(), "expected ')' to close the '(' at " + std::to_string(t.pos + 1) + ", found " +
                                              describe(peek()));
                ++k;
                return true;
            }
            case Tok::Ident: {
                ++k;
                const std::string low = toLower(t.text);
                if (peek().kind == Tok::LParen) {
                    if (low != "abs" && low != "sqrt")
                        return failAt(t, "function '" + t.text + "' unknown (abs and sqrt are)");
                    const Token open = toks[k++];
                    const Token first = peek();
                    int a;
                    Type at_;
                    if (!parseOr(&a, &at_)) return false;
                    if (at_ != Type::Value) return failAt(first, "expected a value inside " + low + "(...)");
                    if (peek().kind != Tok::RParen)
                        return failAt(peek(), "expected ')' to close the '(' at " + std::to_string(open.pos + 1) +
                                                  ", found " + describe(peek()));
                    ++k;
                    n.kind = low == "abs" ? NodeKind::Abs : NodeKind::Sqrt;
                    n.a = a;
                    *node = add(n);
                    *type = Type::Value;
                    return true;
                }
                int col = -1;
                for (size_t i = 0; i < lowColumns.size() && col < 0; ++i)
                    if (lowColumns[i] == low) col = int(i);
                if (col < 0) return failAt(t, "column '" + t.text + "' unknown");
                n.kind = NodeKind::Column;
                n.column = col;
                *node = add(n);
                *type = Type::Value;
                return true;
            }
            case Tok::End: return failAt(t, "expected a value, a column or '(' but the expression ends");
            default: return failAt(t, "expected a value, a column or '(', found " + describe(t));
        }
    }
};

RowFilterResult compileRowFilter(const RowFilterParams& params) {
    RowFilterResult r;
    if (trim(params.text).empty()) {
        r.ok = true;
        r.empty = true;
        return r;
    }
    if (params.text.size() > 4096) {
        r.error = "expression longer than 4096 characters";
        r.errorPos = 4097;
        return r;
    }
    auto f = std::make_shared<RowFilter>();
    RowFilterCompiler c{params, {}, 0, f.get(), {}, 0, 0, {}};
    for (const std::string& col : params.columns) c.lowColumns.push_back(toLower(col));
    if (!lex(params.text, &c.toks, &r.error, &r.errorPos)) return r;
    int root = -1;
    Type type = Type::Bool;
    const Token first = c.peek();
    bool ok = c.parseOr(&root, &type);
    if (ok && c.peek().kind != Tok::End)
        ok = c.failAt(c.peek(), "expected 'and', 'or' or an operator, found " + describe(c.peek()));
    if (ok && type != Type::Bool)
        ok = c.failAt(first, "expected a comparison (such as snr < 10), found a value alone");
    if (!ok) {
        r.error = c.error;
        r.errorPos = c.errorPos;
        if (r.error.rfind("column '", 0) == 0) r.error += "; columns: " + c.columnList();
        return r;
    }
    // The root is the last node added: every parent is added after its children.
    if (root != int(f->m_nodes.size()) - 1) {
        r.error = "internal error: the expression's root is not its last node";
        return r;
    }
    std::vector<bool> used(params.columns.size(), false);
    for (const RowFilterNode& n : f->m_nodes)
        if (n.kind == NodeKind::Column) used[size_t(n.column)] = true;
    for (size_t i = 0; i < used.size(); ++i)
        if (used[i]) f->m_used.push_back(int(i));
    r.ok = true;
    r.filter = std::move(f);
    return r;
}

namespace {

struct Eval {
    const std::vector<RowFilterNode>& nodes;
    const std::vector<FilterCell>& row;

    Value value(int i) const {
        const RowFilterNode& n = nodes[size_t(i)];
        Value v;
        switch (n.kind) {
            case NodeKind::Number: v.number = n.number; return v;
            case NodeKind::Text:
                v.number = n.number;
                v.text = &n.text;
                v.literal = true;
                return v;
            case NodeKind::Column: {
                if (size_t(n.column) >= row.size()) return v;
                const FilterCell& c = row[size_t(n.column)];
                v.number = c.number;
                if (c.isText) v.text = &c.text;
                return v;
            }
            case NodeKind::Neg: v.number = -value(n.a).number; return v;
            case NodeKind::Abs: v.number = std::fabs(value(n.a).number); return v;
            case NodeKind::Sqrt: {
                const double x = value(n.a).number;
                v.number = x >= 0 ? std::sqrt(x) : std::numeric_limits<double>::quiet_NaN();
                return v;
            }
            case NodeKind::Add: v.number = value(n.a).number + value(n.b).number; return v;
            case NodeKind::Sub: v.number = value(n.a).number - value(n.b).number; return v;
            case NodeKind::Mul: v.number = value(n.a).number * value(n.b).number; return v;
            case NodeKind::Div: v.number = value(n.a).number / value(n.b).number; return v;
            default: return v;  // booleans are never values (the compiler checks)
        }
    }

    static int compareText(const Value& a, const Value& b) {
        const std::string& x = *a.text;
        const std::string& y = *b.text;
        const size_t n = std::min(x.size(), y.size());
        for (size_t i = 0; i < n; ++i) {
            const char cx = a.literal ? x[i] : char(std::tolower(static_cast<unsigned char>(x[i])));
            const char cy = b.literal ? y[i] : char(std::tolower(static_cast<unsigned char>(y[i])));
            if (cx != cy) return static_cast<unsigned char>(cx) < static_cast<unsigned char>(cy) ? -1 : 1;
        }
        return x.size() == y.size() ? 0 : (x.size() < y.size() ? -1 : 1);
    }

    bool test(int i) const {
        const RowFilterNode& n = nodes[size_t(i)];
        switch (n.kind) {
            case NodeKind::And: return test(n.a) && test(n.b);
            case NodeKind::Or: return test(n.a) || test(n.b);
            case NodeKind::Not: return !test(n.a);
            case NodeKind::Cmp: {
                const Value a = value(n.a), b = value(n.b);
                int c;
                if (a.text && b.text) {
                    c = compareText(a, b);
                } else {
                    if (std::isnan(a.number) || std::isnan(b.number)) return false;  // missing: false
                    c = a.number < b.number ? -1 : a.number > b.number ? 1 : 0;
                }
                switch (n.op) {
                    case CmpOp::Lt: return c < 0;
                    case CmpOp::Le: return c <= 0;
                    case CmpOp::Gt: return c > 0;
                    case CmpOp::Ge: return c >= 0;
                    case CmpOp::Eq: return c == 0;
                    case CmpOp::Ne: return c != 0;
                }
                return false;
            }
            default: return false;
        }
    }
};

}  // namespace

bool RowFilter::matches(const std::vector<FilterCell>& row) const {
    if (m_nodes.empty()) return true;
    return Eval{m_nodes, row}.test(int(m_nodes.size()) - 1);
}

}  // namespace lwb::core

#include "opencl/kernel_source.hpp"

#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "opencl/error.hpp"

namespace lab::opencl {

namespace {

std::string folder_of(const std::string& path) {
    size_t slash = path.rfind('/');
    return slash == std::string::npos ? std::string() : path.substr(0, slash);
}

// Removes "." and "dir/.." segments so one file always has one name.
std::string normalized(const std::string& path) {
    std::vector<std::string> parts;
    std::stringstream in(path);
    std::string part;
    while (std::getline(in, part, '/')) {
        if (part.empty() || part == ".") continue;
        if (part == ".." && !parts.empty() && parts.back() != "..") parts.pop_back();
        else parts.push_back(part);
    }
    std::string out;
    for (const std::string& p : parts) out += (out.empty() ? "" : "/") + p;
    return out;
}

// The preprocessor lines the assembler reads, taken apart by hand: what it needs of them is a
// directive's name and one or two words after it (std::regex would cost more to compile than the
// rest of the runtime).
bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r'; }
bool is_word(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

size_t skip_blanks(const std::string& s, size_t i) {
    while (i < s.size() && is_blank(s[i])) ++i;
    return i;
}

size_t skip_word(const std::string& s, size_t i) {
    while (i < s.size() && is_word(s[i])) ++i;
    return i;
}

// A line "  #  name rest": the directive's name (its word characters) and where the rest begins.
struct Directive {
    std::string name;
    size_t rest = 0;
};

std::optional<Directive> directive_of(const std::string& line) {
    size_t i = skip_blanks(line, 0);
    if (i >= line.size() || line[i] != '#') return std::nullopt;
    i = skip_blanks(line, i + 1);
    const size_t end = skip_word(line, i);
    return Directive{line.substr(i, end - i), end};
}

// Whether nothing but blanks, then optionally a comment, follows position i.
bool only_comment_after(const std::string& line, size_t i) {
    i = skip_blanks(line, i);
    return i == line.size() || line.compare(i, 2, "//") == 0 || line.compare(i, 2, "/*") == 0;
}

// `#if NAME`, `#if !NAME`, `#ifdef NAME`, `#ifndef NAME`, each alone on its line but for a comment.
struct Switch {
    bool is_ifdef = false;
    bool negate = false;
    std::string name;
};

std::optional<Switch> switch_of(const Directive& d, const std::string& line) {
    Switch sw;
    if (d.name == "if") {
    } else if (d.name == "ifdef" || d.name == "ifndef") {
        sw.is_ifdef = true;
        sw.negate = d.name == "ifndef";
    } else {
        return std::nullopt;
    }
    size_t i = skip_blanks(line, d.rest);
    if (i == d.rest) return std::nullopt;  // a blank must follow the directive
    if (!sw.is_ifdef && i < line.size() && line[i] == '!') {
        sw.negate = true;
        i = skip_blanks(line, i + 1);
    }
    const size_t end = skip_word(line, i);
    if (end == i || !only_comment_after(line, end)) return std::nullopt;
    sw.name = line.substr(i, end - i);
    return sw;
}

// `#define NAME` and its value, the first word after the name when blanks separate them.
struct Definition {
    std::string name;
    std::optional<std::string> value;
    bool bare = false;  // nothing but blanks after the name
};

std::optional<Definition> definition_of(const std::string& line) {
    std::optional<Directive> d = directive_of(line);
    if (!d || d->name != "define") return std::nullopt;
    const size_t i = skip_blanks(line, d->rest);
    const size_t end = skip_word(line, i);
    if (i == d->rest || end == i) return std::nullopt;
    Definition def;
    def.name = line.substr(i, end - i);
    const size_t value = skip_blanks(line, end);
    def.bare = value == line.size();
    if (value > end && value < line.size()) {
        size_t value_end = value;
        while (value_end < line.size() && !is_blank(line[value_end])) ++value_end;
        def.value = line.substr(value, value_end - value);
    }
    return def;
}

// `#include "NAME"`: the name.
std::optional<std::string> include_of(const std::string& line) {
    std::optional<Directive> d = directive_of(line);
    if (!d || d->name != "include") return std::nullopt;
    const size_t open = skip_blanks(line, d->rest);
    if (open >= line.size() || line[open] != '"') return std::nullopt;
    const size_t close = line.find('"', open + 1);
    if (close == std::string::npos || close == open + 1) return std::nullopt;
    return line.substr(open + 1, close - open - 1);
}

// A compiler's "NAME:LINE:COLUMN:" in a build log's line, the first one (NAME: no blank, no colon):
// PoCL writes "error: /cache/tempfile_XXXX.cl:12:5: message". Where NAME begins, the two numbers,
// and where the message after it begins (past its blanks).
struct LogLocation {
    size_t start = 0;
    std::string line, column;
    size_t message = 0;
};

std::optional<LogLocation> log_location_of(const std::string& s) {
    size_t i = 0;
    while (i < s.size()) {
        if (is_blank(s[i]) || s[i] == ':') {
            ++i;
            continue;
        }
        size_t j = i;  // NAME is [i, j); a later start inside it ends at the same j, so fails alike
        while (j < s.size() && !is_blank(s[j]) && s[j] != ':') ++j;
        size_t k = j;
        auto number = [&](std::string* digits) {
            if (k >= s.size() || s[k] != ':') return false;
            const size_t first = ++k;
            while (k < s.size() && is_digit(s[k])) ++k;
            *digits = s.substr(first, k - first);
            return k > first;
        };
        LogLocation at;
        if (number(&at.line) && number(&at.column) && k < s.size() && s[k] == ':') {
            at.start = i;
            at.message = skip_blanks(s, k + 1);
            return at;
        }
        i = j;
    }
    return std::nullopt;
}

// Resolves the conditional blocks that switch parts of a module on and off, so a switched-off part
// (and every file only it includes) never reaches the kernel's source: `#if NAME`, `#if !NAME`,
// `#ifdef NAME` and `#ifndef NAME` where an earlier line, outside any unresolved block, defined NAME
// (`#define NAME 0` or `1` for #if). Everything else, include guards included, passes through to
// the OpenCL compiler untouched, so -D build options keep working.
class Conditionals {
public:
    // Whether `line` is shown to the compiler; updates the block stack and known definitions.
    bool keep(const std::string& line, const std::string& next_line) {
        const std::optional<Directive> d = directive_of(line);
        const bool shown = active();
        if (!d) return shown;  // not a directive: shown where every enclosing block is
        if (const std::optional<Switch> sw = switch_of(*d, line)) {
            Block block;
            if (sw->is_ifdef && sw->negate && is_guard(sw->name, next_line)) {
                block.kind = Block::Guard;  // include guard: passes through, contents count as resolved
            } else if (!shown) {
                block.kind = Block::Resolved;  // inside a dropped block: drop everything
                block.taken = false;
            } else if (sw->is_ifdef && defined_.count(sw->name)) {
                block.kind = Block::Resolved;
                block.taken = !sw->negate;
            } else if (!sw->is_ifdef && values_.count(sw->name) && unresolved_depth_ == 0) {
                block.kind = Block::Resolved;
                block.taken = (values_[sw->name] != 0) != sw->negate;
            } else {
                block.kind = Block::Unresolved;
                ++unresolved_depth_;
            }
            blocks_.push_back(block);
            return shown && block.kind != Block::Resolved;
        }
        if (d->name.compare(0, 2, "if") == 0) {
            blocks_.push_back(Block{shown ? Block::Unresolved : Block::Resolved, false});
            if (shown) ++unresolved_depth_;
            return shown;
        }
        if (blocks_.empty()) {
            record_define(line);
            return true;
        }
        Block& top = blocks_.back();
        if (d->name == "else" || d->name == "elif") {
            if (top.kind != Block::Resolved) return shown;
            if (d->name == "elif") throw OpenClError("#elif after a resolved feature switch is not supported: " + line);
            blocks_.pop_back();
            bool outer = active();
            top.taken = !top.taken && outer;
            blocks_.push_back(top);
            return false;
        }
        if (d->name == "endif") {
            Block block = top;
            blocks_.pop_back();
            if (block.kind == Block::Unresolved) --unresolved_depth_;
            return block.kind == Block::Resolved ? false : active();
        }
        if (shown) record_define(line);
        return shown;
    }

    // Whether the compiler is sure to see what is shown now (no unresolved block encloses it).
    bool certain() const { return unresolved_depth_ == 0; }

private:
    struct Block {
        enum Kind { Guard, Resolved, Unresolved } kind = Unresolved;
        bool taken = true;  // Resolved: whether its lines are shown
    };

    bool active() const {
        for (const Block& b : blocks_)
            if (b.kind == Block::Resolved && !b.taken) return false;
        return true;
    }

    static bool is_guard(const std::string& name, const std::string& next_line) {
        const std::optional<Definition> def = definition_of(next_line);
        return def && def->bare && def->name == name;
    }

    // A definition counts only where the compiler is sure to see it: outside unresolved blocks.
    void record_define(const std::string& line) {
        if (unresolved_depth_ > 0) return;
        const std::optional<Definition> def = definition_of(line);
        if (!def) return;
        defined_.insert(def->name);
        if (def->value == "0" || def->value == "1") values_[def->name] = *def->value == "1";
        else values_.erase(def->name);
    }

    std::vector<Block> blocks_;
    int unresolved_depth_ = 0;
    std::set<std::string> defined_;
    std::map<std::string, int> values_;
};

class Assembler {
public:
    explicit Assembler(const SourceLookup& lookup) : lookup_(lookup) {}

    // A file is expanded once where the compiler is sure to see it; inside an unresolved block
    // (which a -D option may switch off) a later include must expand it again, and its include
    // guard keeps the second copy empty when both are compiled.
    void expand(const std::string& path, AssembledSource* out) {
        if (expanded_.count(path) || expanding_.count(path)) return;
        if (conditionals_.certain()) expanded_.insert(path);
        expanding_.insert(path);
        std::string_view text = lookup_(path);
        std::vector<std::string> lines;
        {
            std::istringstream in{std::string(text)};
            for (std::string line; std::getline(in, line);) lines.push_back(line);
        }
        for (size_t k = 0; k < lines.size(); ++k) {
            const std::string& line = lines[k];
            int number = int(k) + 1;
            if (!conditionals_.keep(line, k + 1 < lines.size() ? lines[k + 1] : std::string())) continue;
            if (const std::optional<std::string> name = include_of(line)) {
                expand(resolve(*name, path, number), out);
                continue;
            }
            out->text += line;
            out->text += '\n';
            out->origin.push_back({path, number});
        }
        expanding_.erase(path);
    }

private:
    std::string resolve(const std::string& name, const std::string& includer, int line) const {
        std::string folder = folder_of(includer);
        std::string beside = normalized(folder.empty() ? name : folder + "/" + name);
        if (!lookup_(beside).empty()) return beside;
        std::string from_root = normalized(name);
        if (!lookup_(from_root).empty()) return from_root;
        throw OpenClError(includer + ":" + std::to_string(line) + ": #include \"" + name +
                          "\": no such embedded file (tried " + beside + " and " + from_root + ")");
    }

    const SourceLookup& lookup_;
    std::set<std::string> expanded_, expanding_;
    Conditionals conditionals_;
};

}  // namespace

SourceLocation AssembledSource::locate(int generated_line) const {
    if (generated_line < 1 || generated_line > int(origin.size())) return {"?", 0};
    return origin[size_t(generated_line - 1)];
}

std::string AssembledSource::line_text(int generated_line) const {
    if (generated_line < 1) return {};
    std::istringstream in(text);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n)
        if (n == generated_line) return line;
    return {};
}

AssembledSource assemble_source(const std::string& entry, const SourceLookup& lookup) {
    std::string path = normalized(entry);
    if (lookup(path).empty()) throw OpenClError("kernel source " + entry + ": no such embedded file");
    AssembledSource out;
    out.entry = path;
    Assembler(lookup).expand(path, &out);
    return out;
}

std::vector<BuildDiagnostic> parse_build_log(const std::string& log, const AssembledSource& source) {
    // PoCL writes "error: /cache/tempfile_XXXX.cl:LINE:COL: message"; other compilers use
    // "<source>:LINE:COL:" or "<kernel>:LINE:COL:". Any non-blank name before LINE:COL: will do.
    std::vector<BuildDiagnostic> found;
    std::istringstream in(log);
    std::string line;
    while (std::getline(in, line)) {
        const std::optional<LogLocation> at = log_location_of(line);
        if (!at) continue;
        BuildDiagnostic d;
        d.generated_line = std::stoi(at->line);
        d.column = std::stoi(at->column);
        d.origin = source.locate(d.generated_line);
        // "error: " or "warning: " in PoCL's layout, then the message
        d.message = line.substr(0, at->start) + line.substr(at->message);
        found.push_back(d);
    }
    return found;
}

std::string annotate_build_log(const std::string& log, const AssembledSource& source) {
    std::vector<BuildDiagnostic> diagnostics = parse_build_log(log, source);
    std::ostringstream out;
    std::istringstream in(log);
    std::string line;
    size_t next = 0;
    while (std::getline(in, line)) {
        out << line << '\n';
        if (next < diagnostics.size() && log_location_of(line)) {
            const BuildDiagnostic& d = diagnostics[next++];
            out << "    at " << d.origin.file << ':' << d.origin.line << " (generated line " << d.generated_line
                << "): " << source.line_text(d.generated_line) << '\n';
        }
    }
    return out.str();
}

}  // namespace lab::opencl

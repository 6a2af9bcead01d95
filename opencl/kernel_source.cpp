#include "opencl/kernel_source.hpp"

#include <map>
#include <regex>
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

// Resolves the conditional blocks that switch parts of a module on and off, so a switched-off part
// (and every file only it includes) never reaches the kernel's source: `#if NAME`, `#if !NAME`,
// `#ifdef NAME` and `#ifndef NAME` where an earlier line, outside any unresolved block, defined NAME
// (`#define NAME 0` or `1` for #if). Everything else, include guards included, passes through to
// the OpenCL compiler untouched, so -D build options keep working.
class Conditionals {
public:
    // Whether `line` is shown to the compiler; updates the block stack and known definitions.
    bool keep(const std::string& line, const std::string& next_line) {
        static const std::regex if_line(R"re(^\s*#\s*if\s+(!?)\s*(\w+)\s*(//.*|/\*.*)?$)re");
        static const std::regex ifdef_line(R"re(^\s*#\s*if(n?)def\s+(\w+)\s*(//.*|/\*.*)?$)re");
        static const std::regex other_if(R"re(^\s*#\s*if.*$)re");
        static const std::regex else_line(R"re(^\s*#\s*else\b.*$)re");
        static const std::regex elif_line(R"re(^\s*#\s*elif\b.*$)re");
        static const std::regex endif_line(R"re(^\s*#\s*endif\b.*$)re");
        static const std::regex define_line(R"re(^\s*#\s*define\s+(\w+)(\s+(\S+))?.*$)re");
        std::smatch m;
        bool shown = active();
        if (std::regex_match(line, m, if_line) || std::regex_match(line, m, ifdef_line)) {
            bool is_ifdef = line.find("def") != std::string::npos && std::regex_match(line, ifdef_line);
            std::string name = m[2].str();
            bool negate = m[1].str() == "!" || m[1].str() == "n";
            Block block;
            if (is_ifdef && negate && is_guard(name, next_line)) {
                block.kind = Block::Guard;  // include guard: passes through, contents count as resolved
            } else if (!shown) {
                block.kind = Block::Resolved;  // inside a dropped block: drop everything
                block.taken = false;
            } else if (is_ifdef && defined_.count(name)) {
                block.kind = Block::Resolved;
                block.taken = negate ? false : true;
            } else if (!is_ifdef && values_.count(name) && unresolved_depth_ == 0) {
                block.kind = Block::Resolved;
                block.taken = (values_[name] != 0) != negate;
            } else {
                block.kind = Block::Unresolved;
                ++unresolved_depth_;
            }
            blocks_.push_back(block);
            return shown && block.kind != Block::Resolved;
        }
        if (std::regex_match(line, other_if)) {
            blocks_.push_back(Block{shown ? Block::Unresolved : Block::Resolved, false});
            if (shown) ++unresolved_depth_;
            return shown;
        }
        if (blocks_.empty()) {
            record_define(line, define_line);
            return true;
        }
        Block& top = blocks_.back();
        if (std::regex_match(line, else_line) || std::regex_match(line, elif_line)) {
            if (top.kind != Block::Resolved) return shown;
            if (std::regex_match(line, elif_line))
                throw OpenClError("#elif after a resolved feature switch is not supported: " + line);
            blocks_.pop_back();
            bool outer = active();
            top.taken = !top.taken && outer;
            blocks_.push_back(top);
            return false;
        }
        if (std::regex_match(line, endif_line)) {
            Block block = top;
            blocks_.pop_back();
            if (block.kind == Block::Unresolved) --unresolved_depth_;
            return block.kind == Block::Resolved ? false : active();
        }
        if (shown) record_define(line, define_line);
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
        static const std::regex bare_define(R"re(^\s*#\s*define\s+(\w+)\s*$)re");
        std::smatch m;
        return std::regex_match(next_line, m, bare_define) && m[1].str() == name;
    }

    // A definition counts only where the compiler is sure to see it: outside unresolved blocks.
    void record_define(const std::string& line, const std::regex& define_line) {
        std::smatch m;
        if (unresolved_depth_ > 0 || !std::regex_match(line, m, define_line)) return;
        defined_.insert(m[1].str());
        if (m[3].matched && (m[3].str() == "0" || m[3].str() == "1")) values_[m[1].str()] = m[3].str() == "1";
        else values_.erase(m[1].str());
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
        static const std::regex include_line(R"re(^\s*#\s*include\s*"([^"]+)".*$)re");
        for (size_t k = 0; k < lines.size(); ++k) {
            const std::string& line = lines[k];
            int number = int(k) + 1;
            if (!conditionals_.keep(line, k + 1 < lines.size() ? lines[k + 1] : std::string())) continue;
            std::smatch match;
            if (std::regex_match(line, match, include_line)) {
                expand(resolve(match[1].str(), path, number), out);
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
    static const std::regex location(R"(([^\s:]+):(\d+):(\d+):\s*(.*)$)");
    std::vector<BuildDiagnostic> found;
    std::istringstream in(log);
    std::string line;
    while (std::getline(in, line)) {
        std::smatch match;
        if (!std::regex_search(line, match, location)) continue;
        BuildDiagnostic d;
        d.generated_line = std::stoi(match[2].str());
        d.column = std::stoi(match[3].str());
        d.origin = source.locate(d.generated_line);
        std::string prefix = match.prefix().str();  // "error: " or "warning: " in PoCL's layout
        d.message = prefix + match[4].str();
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
    static const std::regex location(R"(([^\s:]+):(\d+):(\d+):)");
    while (std::getline(in, line)) {
        out << line << '\n';
        if (next < diagnostics.size() && std::regex_search(line, location)) {
            const BuildDiagnostic& d = diagnostics[next++];
            out << "    at " << d.origin.file << ':' << d.origin.line << " (generated line " << d.generated_line
                << "): " << source.line_text(d.generated_line) << '\n';
        }
    }
    return out.str();
}

}  // namespace lab::opencl

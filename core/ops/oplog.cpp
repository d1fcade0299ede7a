#include "ops/oplog.hpp"

#include "geometry/step_geometry.hpp"
#include "ops/op_table.hpp"

namespace hexdual {

namespace {

[[noreturn]] void fail(size_t pos, const std::string& why, std::string_view token) {
  throw Error("oplog: position " + std::to_string(pos) + ": " + why + " at '" + std::string(token) + "'");
}

// Reads digits at s[i...]; returns -1 when none.
int64_t readInt(std::string_view s, size_t& i) {
  size_t b = i;
  int64_t v = 0;
  while (i < s.size() && s[i] >= '0' && s[i] <= '9' && i - b < 9) v = v * 10 + (s[i++] - '0');
  if (i == b || (i < s.size() && s[i] >= '0' && s[i] <= '9')) return -1;
  return v;
}

// One entity "h12", "h12f3", "h12.f3", "h12e7"; returns false on malformed text.
bool parseEntity(std::string_view t, OpArg& out) {
  size_t i = 0;
  if (t.empty() || t[i++] != 'h') return false;
  int64_t h = readInt(t, i);
  if (h < 0) return false;
  out.hex = HexId(h);
  if (i == t.size()) {
    out.kind = OpArg::Hex;
    return true;
  }
  if (t[i] == '.') ++i;
  if (i >= t.size() || (t[i] != 'f' && t[i] != 'e')) return false;
  out.kind = t[i] == 'f' ? OpArg::Quad : OpArg::Edge;
  ++i;
  int64_t l = readInt(t, i);
  if (l < 0 || i != t.size()) return false;
  out.local = int(l);
  return true;
}

}  // namespace

OpStep parseOpStep(std::string_view text, size_t offset) {
  OpStep step;
  step.position = offset;
  size_t i = 0;
  std::vector<std::pair<std::string_view, size_t>> tokens;
  tokens.reserve(8);  // an operation and its arguments: one allocation
  while (i < text.size()) {
    if (text[i] == ' ') {
      if (i == 0 || i + 1 == text.size() || text[i + 1] == ' ') fail(offset + i, "stray space", text);
      ++i;
      continue;
    }
    size_t b = i;
    while (i < text.size() && text[i] != ' ') ++i;
    tokens.push_back({text.substr(b, i - b), offset + b});
  }
  if (tokens.empty()) fail(offset, "empty step", text);
  const OpInfo* spec = findOp(tokens[0].first);
  if (!spec) fail(tokens[0].second, "unknown operation", tokens[0].first);
  step.op = spec->kind;
  const bool list = spec->variadic;
  size_t want = spec->args.size();
  if (list ? tokens.size() < 2 : tokens.size() - 1 != want)
    fail(tokens[0].second, std::string(spec->name) + " takes " + (list ? "one or more" : std::to_string(want)) +
                               " argument(s), not " + std::to_string(tokens.size() - 1),
         text);
  step.args.reserve(tokens.size() - 1);
  for (size_t k = 1; k < tokens.size(); ++k) {
    auto [tok, pos] = tokens[k];
    OpArg::Kind kind = list ? spec->args[0] : spec->args[k - 1];
    OpArg a;
    if (kind == OpArg::Number) {
      size_t i = 0;
      const int64_t v = readInt(tok, i);
      if (v < 0 || i != tok.size()) fail(pos, std::string("expected ") + argKindName(kind), tok);
      a = OpArg::of(Count{int(v)});
    } else if (kind == OpArg::Pair) {
      size_t slash = tok.find('/');
      OpArg second;
      if (slash == std::string_view::npos || !parseEntity(tok.substr(0, slash), a) ||
          !parseEntity(tok.substr(slash + 1), second) || a.kind != OpArg::Quad || second.kind != OpArg::Quad)
        fail(pos, std::string("expected ") + argKindName(kind), tok);
      a.kind = OpArg::Pair;
      a.second = {second.hex, second.local};
    } else if (!parseEntity(tok, a) || a.kind != kind) {
      fail(pos, std::string("expected ") + argKindName(kind), tok);
    }
    step.args.push_back(a);
  }
  return step;
}

OpLog parseOpLog(std::string_view text) {
  OpLog log;
  size_t end = text.find(';');
  std::string_view head = text.substr(0, end);
  if (head != "v1") fail(0, "a log starts with its version 'v1'", head);
  size_t pos = end == std::string_view::npos ? text.size() : end + 1;
  while (end != std::string_view::npos) {
    end = text.find(';', pos);
    std::string_view stepText = text.substr(pos, end == std::string_view::npos ? std::string_view::npos : end - pos);
    log.steps.push_back(parseOpStep(stepText, pos));
    pos = end + 1;
  }
  return log;
}

std::string formatOpStep(const OpStep& step) {
  std::string s = opName(step.op);
  for (const OpArg& a : step.args) s += " " + entityName(a);
  return s;
}

std::string formatOpLog(const OpLog& log) {
  std::string s = "v" + std::to_string(log.version);
  for (const OpStep& st : log.steps) s += ";" + formatOpStep(st);
  return s;
}

std::string encodeOpLogUrl(const OpLog& log) {
  std::string s = std::to_string(log.version);
  for (const OpStep& st : log.steps) {
    s += "." + std::string(1, opInfo(st.op).urlCode);
    for (size_t k = 0; k < st.args.size(); ++k) {
      const OpArg& a = st.args[k];
      if (k) s += "_";
      if (a.kind == OpArg::Number) {  // a number keeps its digits: the decoder knows the argument kinds
        s += std::to_string(a.local);
        continue;
      }
      s += std::to_string(a.hex);
      if (a.kind == OpArg::Quad || a.kind == OpArg::Pair) s += "f" + std::to_string(a.local);
      if (a.kind == OpArg::Edge) s += "e" + std::to_string(a.local);
      if (a.kind == OpArg::Pair) s += "~" + std::to_string(a.second.hex) + "f" + std::to_string(a.second.face);
    }
  }
  return s;
}

OpLog decodeOpLogUrl(std::string_view text) {
  // Translate back to the text form, then parse it strictly.
  for (size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    bool ok = (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '.' || c == '_' || c == '~';
    if (!ok) fail(i, "character not allowed in a URL-encoded log", text.substr(i, 1));
  }
  size_t dot = text.find('.');
  std::string out = "v" + std::string(text.substr(0, dot));
  size_t pos = dot;
  while (pos != std::string_view::npos) {
    size_t next = text.find('.', pos + 1);
    std::string_view step = text.substr(pos + 1, next == std::string_view::npos ? std::string_view::npos : next - pos - 1);
    if (step.empty()) fail(pos, "empty step", text.substr(pos));
    const OpInfo* spec = findOpByUrlCode(step[0]);
    if (!spec) fail(pos + 1, "unknown operation code", step.substr(0, 1));
    out += ";" + std::string(spec->name);
    std::string args(step.substr(1));
    // An entity gets its 'h' back; a number argument (none before the sheet family) does not.
    auto argStart = [&](size_t k) {
      const size_t i = spec->variadic ? 0 : k;
      return i < spec->args.size() && spec->args[i] == OpArg::Number ? " " : " h";
    };
    if (!args.empty()) {
      size_t k = 0;
      out += argStart(k);
      for (char c : args) {
        if (c == '_') out += argStart(++k);
        else if (c == '~') out += "/h";
        else out += c;
      }
    }
    pos = next;
  }
  return parseOpLog(out);
}

namespace {
// The operation's result with its geometry placed and measured (after the operation committed).
OpResult withGeometry(Complex& cx, OpResult r, const StepOptions& options) {
  r.quality = placeStepGeometry(cx, r.edits, options.geometry);
  return r;
}
}  // namespace

OpResult applyStep(Complex& cx, const OpStep& st, const StepOptions& options) {
  checkArgs(st);
  return withGeometry(cx, opInfo(st.op).apply(cx, st), options);
}

OpResult applyStep(Complex& cx, std::string_view stepText, const StepOptions& options) {
  return applyStep(cx, parseOpStep(stepText), options);
}

std::string precheckStep(const Complex& cx, const OpStep& st) {
  checkArgs(st);
  const OpInfo& info = opInfo(st.op);
  return info.precheck ? info.precheck(cx, st) : std::string();
}

std::optional<OpResult> tryApplyStep(Complex& cx, const OpStep& st, std::string* why, const StepOptions& options) {
  try {
    checkArgs(st);
    const OpInfo& info = opInfo(st.op);
    if (info.precheck) {
      std::string problem = info.precheck(cx, st);
      if (!problem.empty()) {
        if (why) *why = std::move(problem);
        return std::nullopt;
      }
    }
    return withGeometry(cx, info.apply(cx, st), options);
  } catch (const Error& e) {
    if (why) *why = e.what();
    return std::nullopt;
  }
}

std::optional<OpResult> tryApplyStep(Complex& cx, std::string_view stepText, std::string* why, const StepOptions& options) {
  OpStep st;
  try {
    st = parseOpStep(stepText);
  } catch (const Error& e) {
    if (why) *why = e.what();
    return std::nullopt;
  }
  return tryApplyStep(cx, st, why, options);
}

ApplyReport applyLog(Complex& cx, const OpLog& log, const StepOptions& options) {
  ApplyReport rep;
  for (size_t k = 0; k < log.steps.size(); ++k) {
    try {
      rep.results.push_back(applyStep(cx, log.steps[k], options));
    } catch (const Error& e) {
      rep.failedStep = int(k + 1);
      rep.error = e.what();
      break;
    }
  }
  return rep;
}

ApplyReport applyLog(Complex& cx, std::string_view logText, const StepOptions& options) {
  OpLog log;
  try {
    log = parseOpLog(logText);
  } catch (const Error& e) {
    ApplyReport rep;
    rep.failedStep = -1;
    rep.error = e.what();
    return rep;
  }
  return applyLog(cx, log, options);
}

}  // namespace hexdual

#include "RunOutcome.hpp"

#include "Bytes.hpp"

namespace sylva::assess {

namespace {

template <class T>
void putAll(ByteWriter& w, const std::vector<T>& items) {
    w.put(static_cast<std::uint64_t>(items.size()));
    for (const T& item : items) w.put(item);
}
template <class T>
std::vector<T> getAll(ByteReader& r) {
    std::vector<T> items(r.count(sizeof(T)));
    for (T& item : items) item = r.get<T>();
    return items;
}

}  // namespace

std::string encode(const RunOutcome& o) {
    ByteWriter w;
    const BlockTrace& t = o.trace;
    putAll(w, t.passages);
    w.put(t.depositCell);
    putAll(w, t.impactCells);
    w.put(t.pathLengthM).put(t.reachM).put(t.reason).put(static_cast<std::uint64_t>(o.volumeClass));
    putAll(w, o.crossings);
    const BlockPath& p = o.path;
    w.put(p.run).put(p.seed).put(p.releaseColumn).put(p.releaseRow).put(p.reason).put(p.pathLengthM).put(p.reachM);
    putAll(w, p.points);
    putAll(w, o.impacts);
    return w.take();
}

RunOutcome decode(const std::string& bytes) {
    ByteReader r(bytes);
    RunOutcome o;
    BlockTrace& t = o.trace;
    t.passages = getAll<CellPassage>(r);
    t.depositCell = r.get<long>();
    t.impactCells = getAll<std::uint32_t>(r);
    t.pathLengthM = r.get<double>();
    t.reachM = r.get<double>();
    t.reason = r.get<dem::StopReason>();
    o.volumeClass = static_cast<std::size_t>(r.get<std::uint64_t>());
    o.crossings = getAll<LineCrossing>(r);
    BlockPath& p = o.path;
    p.run = r.get<long>();
    p.seed = r.get<std::uint64_t>();
    p.releaseColumn = r.get<int>();
    p.releaseRow = r.get<int>();
    p.reason = r.get<dem::StopReason>();
    p.pathLengthM = r.get<double>();
    p.reachM = r.get<double>();
    p.points = getAll<PathPoint>(r);
    o.impacts = getAll<ImpactPoint>(r);
    r.end();
    return o;
}

}  // namespace sylva::assess

#include "voronav/dds/cyclone_config.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "voronav/core/error.hpp"

namespace voronav::dds {
namespace {

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out.push_back(c);
    }
  }
  return out;
}

bool looks_like_address(const std::string& s) {
  // IPv4 dotted quad or IPv6 (contains ':'): otherwise taken as an interface name.
  if (s.find(':') != std::string::npos) return true;
  for (char c : s)
    if (!(c == '.' || (c >= '0' && c <= '9'))) return false;
  return true;
}

std::string duration(double s) {
  std::ostringstream os;
  os << static_cast<long long>(std::llround(s * 1000.0)) << " ms";
  return os.str();
}

}  // namespace

std::string cyclone_config_xml(const CycloneConfigOptions& o) {
  if (o.interface.empty()) throw Error("interface", 0, "expected an address or interface name");
  if (o.peers.empty()) throw Error("peers", 0, "expected at least one discovery peer");
  for (const auto& p : o.peers)
    if (p.empty()) throw Error("peers", 0, "empty peer address");
  if (o.max_auto_participant_index < 0 || o.max_auto_participant_index > 119)
    throw Error("max_auto_participant_index", 0,
                "expected 0..119, got " + std::to_string(o.max_auto_participant_index));
  if (!(o.lease_duration_s > 0.0) || !std::isfinite(o.lease_duration_s))
    throw Error("lease_duration_s", 0, "expected a positive number of seconds");
  if (!(o.spdp_interval_s > 0.0) || !std::isfinite(o.spdp_interval_s))
    throw Error("spdp_interval_s", 0, "expected a positive number of seconds");

  std::ostringstream x;
  x << "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
    << "<CycloneDDS xmlns=\"https://cdds.io/config\">\n"
    << "  <Domain Id=\"any\">\n"
    << "    <General>\n"
    << "      <Interfaces>\n"
    << "        <NetworkInterface " << (looks_like_address(o.interface) ? "address" : "name")
    << "=\"" << xml_escape(o.interface) << "\"/>\n"
    << "      </Interfaces>\n"
    << "      <AllowMulticast>" << (o.allow_multicast ? "true" : "false") << "</AllowMulticast>\n"
    << "    </General>\n"
    << "    <Discovery>\n"
    << "      <ParticipantIndex>auto</ParticipantIndex>\n"
    << "      <MaxAutoParticipantIndex>" << o.max_auto_participant_index
    << "</MaxAutoParticipantIndex>\n"
    << "      <LeaseDuration>" << duration(o.lease_duration_s) << "</LeaseDuration>\n"
    << "      <SPDPInterval>" << duration(o.spdp_interval_s) << "</SPDPInterval>\n"
    << "      <Peers>\n";
  for (const auto& p : o.peers)
    x << "        <Peer address=\"" << xml_escape(p) << "\"/>\n";
  x << "      </Peers>\n"
    << "    </Discovery>\n"
    << "  </Domain>\n"
    << "</CycloneDDS>\n";
  return x.str();
}

std::string loopback_config_xml() {
  return cyclone_config_xml(CycloneConfigOptions{});
}

void write_cyclone_config(const std::filesystem::path& path, const CycloneConfigOptions& options) {
  const std::string xml = cyclone_config_xml(options);
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  if (!f) throw Error(path.string(), 0, "cannot open for writing");
  f << xml;
  f.close();
  if (!f) throw Error(path.string(), 0, "write failed");
}

std::string cyclone_uri_for(const std::filesystem::path& path) {
  return "file://" + std::filesystem::absolute(path).string();
}

}  // namespace voronav::dds

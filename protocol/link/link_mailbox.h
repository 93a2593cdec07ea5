// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "connection_report.h"
#include "link_settings.h"
#include "link_status.h"
#include "oi_command.h"
#include "recording_markers.h"
#include "replay_control.h"
#include "sensor_snapshot.h"

#include <QByteArray>
#include <QList>
#include <QMetaType>
#include <QString>

#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace oilink {

class RobotLink;

// What a robot's model asks of its link, as one value: it crosses to the
// link's thread whole, and the link's public slots do it there.
namespace request {
struct Open { LinkSettings settings; };
struct Close {};
struct Send { std::vector<oi::OiCommand> commands; };  // RobotLink::send
struct QuerySensors { QList<int> packetIds; bool internal = false; };
struct ShowScript {};
struct CheckConnection {};
struct Wake {};
struct StartRecording { QString path; };
struct StopRecording {};
struct MarkRecording { MarkerEdit edit; };
struct ControlReplay { ReplayCommand command; };
} // namespace request

using LinkRequest = std::variant<request::Open, request::Close, request::Send, request::QuerySensors,
                                 request::ShowScript, request::CheckConnection, request::Wake,
                                 request::StartRecording, request::StopRecording, request::MarkRecording,
                                 request::ControlReplay>;

// Does `r` with the link's public slots, on the link's thread.
void applyRequest(RobotLink &link, const LinkRequest &r);

// What the link said, as one value each, in the order it said them (the
// signals of RobotLink of the same names).
namespace event {
struct Frame { oi::SensorSnapshot snapshot; double readSeconds = 0; };
struct BytesReceived { QByteArray bytes; double readSeconds = 0; };
struct BytesSent { QByteArray bytes; std::vector<oi::OiCommand> commands; double sentSeconds = 0; };
struct State { LinkState state = LinkState::Closed; };
struct Statistics { LinkStats stats; };
struct StreamStarted { oi::ProfileId profile = oi::ProfileId::Create2; int baud = 0; QList<int> packets; };
struct ProfileAssumed { oi::ProfileId assumed = oi::ProfileId::Create2; };
struct ModeReportedOneHigh {};
struct SensorReply { oi::SensorSnapshot reply; };
struct ScriptReply { QByteArray script; };
struct ScriptFailed { QString message; };
struct CheckStep { QString step; };
struct ConnectionChecked { ConnectionReport report; };
struct RobotText { QString line; };
struct Error { QString message; };
struct Recording { RecordingStatus status; };
struct Replay { ReplayStatus status; };
} // namespace event

using LinkEvent = std::variant<event::Frame, event::BytesReceived, event::BytesSent, event::State,
                               event::Statistics, event::StreamStarted, event::ProfileAssumed,
                               event::ModeReportedOneHigh, event::SensorReply, event::ScriptReply,
                               event::ScriptFailed, event::CheckStep, event::ConnectionChecked, event::RobotText,
                               event::Error, event::Recording, event::Replay>;

// An event's fields in order, as the link's signal of its name carries them.
inline auto fields(const event::Frame &e) { return std::tie(e.snapshot, e.readSeconds); }
inline auto fields(const event::BytesReceived &e) { return std::tie(e.bytes, e.readSeconds); }
inline auto fields(const event::BytesSent &e) { return std::tie(e.bytes, e.commands, e.sentSeconds); }
inline auto fields(const event::State &e) { return std::tie(e.state); }
inline auto fields(const event::Statistics &e) { return std::tie(e.stats); }
inline auto fields(const event::StreamStarted &e) { return std::tie(e.profile, e.baud, e.packets); }
inline auto fields(const event::ProfileAssumed &e) { return std::tie(e.assumed); }
inline auto fields(const event::ModeReportedOneHigh &) { return std::tuple<>(); }
inline auto fields(const event::SensorReply &e) { return std::tie(e.reply); }
inline auto fields(const event::ScriptReply &e) { return std::tie(e.script); }
inline auto fields(const event::ScriptFailed &e) { return std::tie(e.message); }
inline auto fields(const event::CheckStep &e) { return std::tie(e.step); }
inline auto fields(const event::ConnectionChecked &e) { return std::tie(e.report); }
inline auto fields(const event::RobotText &e) { return std::tie(e.line); }
inline auto fields(const event::Error &e) { return std::tie(e.message); }
inline auto fields(const event::Recording &e) { return std::tie(e.status); }
inline auto fields(const event::Replay &e) { return std::tie(e.status); }

// Calls `handler` with the event itself, or else with as many of its
// leading fields as it takes (as a slot may take fewer than its signal).
template <typename Kind, typename Handler>
void handEvent(Handler &handler, const Kind &k)
{
    if constexpr (std::is_invocable_v<Handler &, const Kind &>) {
        handler(k);
    } else {
        const auto all = fields(k);
        using All = std::remove_cvref_t<decltype(all)>;
        const auto leading = [&]<std::size_t N>(auto &self) {
            if constexpr ([]<std::size_t... I>(std::index_sequence<I...>) {
                              return std::is_invocable_v<Handler &, std::tuple_element_t<I, All>...>;
                          }(std::make_index_sequence<N>{}))
                [&]<std::size_t... I>(std::index_sequence<I...>) { handler(std::get<I>(all)...); }(
                    std::make_index_sequence<N>{});
            else if constexpr (N > 0)
                self.template operator()<N - 1>(self);
            else
                static_assert(N > 0, "the handler takes neither the event nor its leading fields");
        };
        leading.template operator()<std::tuple_size_v<All>>(leading);
    }
}

// Frames and the bytes they came in wait for the next delivery; anything
// else is handed out at once, after them.
inline bool waitsForDelivery(const LinkEvent &e)
{
    return std::holds_alternative<event::Frame>(e) || std::holds_alternative<event::BytesReceived>(e);
}

// For std::visit over a LinkEvent with one lambda per kind.
template <typename... Handlers>
struct Overloaded : Handlers... {
    using Handlers::operator()...;
};
template <typename... Handlers>
Overloaded(Handlers...) -> Overloaded<Handlers...>;

// Calls `handler` with the event when it is of kind `Kind`.
template <typename Kind, typename Handler>
void onEvent(const LinkEvent &e, Handler &&handler)
{
    if (const Kind *k = std::get_if<Kind>(&e))
        handler(*k);
}

} // namespace oilink

Q_DECLARE_METATYPE(oilink::LinkEvent)
Q_DECLARE_METATYPE(oilink::LinkRequest)

// SPDX-License-Identifier: GPL-3.0-or-later
// Renders Foxglove Studio's App as its web build does, with the data sources
// a user opens a robot or a recording with (Foxglove WebSocket, remote file),
// one layout (/layout.json, given as layoutId=roomba-r1) and settings kept in
// memory, so nothing outlives the page. The data source comes from the page's
// own address (?ds=…&ds.url=…), Studio's deep links.
"use strict";
(async () => {
  const layoutData = await (await fetch("/layout.json")).json();
  const layouts = new Map();
  layouts.set("roomba-r1", {
    id: "roomba-r1",
    name: "roomba-r1",
    permission: "CREATOR_WRITE",
    baseline: { data: layoutData, savedAt: undefined },
    working: undefined,
    syncInfo: undefined,
  });
  const layoutStorage = {
    list: async () => [...layouts.values()],
    get: async (_namespace, id) => layouts.get(id),
    put: async (_namespace, layout) => (layouts.set(layout.id, layout), layout),
    delete: async (_namespace, id) => void layouts.delete(id),
    importLayouts: async () => {},
  };
  // Times as seconds, to the nanosecond.
  const settings = new Map([["time.format", "SEC"], ["colorScheme", "light"]]);
  const listeners = new Map();
  const appConfiguration = {
    get: (key) => settings.get(key),
    set: async (key, value) => {
      settings.set(key, value);
      for (const listener of listeners.get(key) ?? []) listener(value);
    },
    addChangeListener: (key, listener) => listeners.set(key, [...(listeners.get(key) ?? []), listener]),
    removeChangeListener: (key, listener) => listeners.set(key, (listeners.get(key) ?? []).filter((l) => l !== listener)),
  };
  await self.initI18n();
  ReactDOM.render(
    React.createElement(self.App, {
      deepLinks: [location.href],
      appConfiguration,
      dataSources: [new self.FoxgloveWebSocketDataSourceFactory(), new self.RemoteDataSourceFactory()],
      layoutStorage,
      extensionLoaders: [],
      enableGlobalCss: true,
    }),
    document.getElementById("root"),
  );
})().catch((e) => {
  window.studioPageError = String(e?.stack ?? e);
});

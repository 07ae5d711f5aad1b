// An OPC UA client built on node-opcua (a stack we did not write), driven by the tests.
// Usage: node client.js '<json options>'; then one JSON command per line on stdin, one JSON
// answer per line on stdout (prefixed with "@@ " so node-opcua's own warnings can be told
// apart). Commands: connect, read, browse, methods, subscribe, call, write, quit.
"use strict";
const readline = require("readline");
const {
  OPCUAClient, MessageSecurityMode, SecurityPolicy, AttributeIds, UserTokenType,
  ClientSubscription, ClientMonitoredItem, TimestampsToReturn, constructEventFilter,
  makeBrowsePath, DataType, NodeClass, BrowseDirection,
} = require("node-opcua-client");
const { OPCUACertificateManager } = require("node-opcua-certificate-manager");

const options = JSON.parse(process.argv[2]);
let client = null;
let session = null;
let ns = {};

function plain(variant) {
  // UInt64 and Int64 arrive as [high, low] 32-bit words; LocalizedText as an object.
  const v = variant.value;
  if (variant.dataType === DataType.UInt64 || variant.dataType === DataType.Int64) {
    return v[0] * 4294967296 + v[1];
  }
  if (v && typeof v === "object" && "text" in v) return v.text;
  return v;
}

function say(obj) { process.stdout.write("@@ " + JSON.stringify(obj) + "\n"); }

function pathOf(parts) {
  // parts like ["Machinery:Machines", "own:StaveJointer", "Woodworking:State"]
  return "/Objects/" + parts.map((p) => {
    const [uri, name] = p.split(":");
    return `${ns[uri]}:${name}`;
  }).join("/");
}

async function resolve(parts) {
  const result = await session.translateBrowsePath(makeBrowsePath("RootFolder", pathOf(parts)));
  if (!result.targets || result.targets.length === 0) {
    throw new Error("no node at " + parts.join("/") + ": " + result.statusCode.toString());
  }
  return result.targets[0].targetId;
}

const URIS = {
  Machinery: "http://opcfoundation.org/UA/Machinery/",
  DI: "http://opcfoundation.org/UA/DI/",
  Woodworking: "http://opcfoundation.org/UA/Woodworking/",
  own: "urn:stave-jointer:opcua",
};

async function connect(cmd) {
  const certificateManager = new OPCUACertificateManager({
    rootFolder: options.pki, automaticallyAcceptUnknownCertificate: true,
  });
  client = OPCUAClient.create({
    applicationName: "StaveJointerTestClient",
    applicationUri: "urn:stave-jointer:test-client",
    securityMode: MessageSecurityMode[cmd.mode || "SignAndEncrypt"],
    securityPolicy: SecurityPolicy[cmd.policy || "Basic256Sha256"],
    endpointMustExist: true,
    connectionStrategy: { maxRetry: 0, initialDelay: 100, maxDelay: 200 },
    clientCertificateManager: certificateManager,
    requestedSessionTimeout: 60000,
  });
  await client.connect(options.endpoint);
  const identity = cmd.user
    ? { type: UserTokenType.UserName, userName: cmd.user, password: cmd.password }
    : { type: UserTokenType.Anonymous };
  session = await client.createSession(identity);
  const nsArray = (await session.read({ nodeId: "ns=0;i=2255", attributeId: AttributeIds.Value })).value.value;
  for (const [key, uri] of Object.entries(URIS)) { ns[key] = nsArray.indexOf(uri); }
  return { ok: true, ns };
}

async function read(cmd) {
  const out = {};
  for (const [key, parts] of Object.entries(cmd.paths)) {
    const nodeId = await resolve(parts);
    const dv = await session.read({ nodeId, attributeId: AttributeIds.Value });
    out[key] = plain(dv.value);
  }
  return { ok: true, values: out };
}

async function browse(cmd) {
  const nodeId = await resolve(cmd.path);
  const result = await session.browse({ nodeId, browseDirection: BrowseDirection.Forward, resultMask: 63 });
  return { ok: true, names: result.references.map((r) => r.browseName.name) };
}

async function methods(cmd) {
  // Every method below the machine object, at any depth.
  const root = await resolve(cmd.path);
  const found = [];
  const seen = new Set();
  async function walk(nodeId, depth) {
    if (depth > 8 || seen.has(nodeId.toString())) return;
    seen.add(nodeId.toString());
    const result = await session.browse({ nodeId, browseDirection: BrowseDirection.Forward, resultMask: 63,
      referenceTypeId: "HierarchicalReferences", includeSubtypes: true });
    for (const ref of result.references) {
      if (ref.nodeClass === NodeClass.Method) found.push(ref.browseName.name);
      else if (ref.nodeClass === NodeClass.Object) await walk(ref.nodeId, depth + 1);
    }
  }
  await walk(root, 0);
  return { ok: true, methods: found };
}

let subscription = null;
async function subscribe(cmd) {
  subscription = ClientSubscription.create(session, {
    requestedPublishingInterval: cmd.interval_ms || 100, requestedLifetimeCount: 600,
    requestedMaxKeepAliveCount: 20, maxNotificationsPerPublish: 1000, publishingEnabled: true, priority: 1,
  });
  await new Promise((res) => subscription.on("started", res));
  for (const [key, parts] of Object.entries(cmd.values || {})) {
    const nodeId = await resolve(parts);
    const item = await subscription.monitor({ nodeId, attributeId: AttributeIds.Value },
      { samplingInterval: cmd.interval_ms || 100, discardOldest: false, queueSize: 1000 }, TimestampsToReturn.Both);
    item.on("changed", (dv) => {
      say({ notification: key, value: plain(dv.value), t: Date.now() });
    });
  }
  if (cmd.events) {
    const nodeId = await resolve(cmd.events);
    const fields = ["Message", "Severity", `${ns.Woodworking}:MessageId`, `${ns.Woodworking}:LocalizedMessages`, `${ns.Woodworking}:EventCategory`, `${ns.Woodworking}:Arguments`];
    const item = await subscription.monitor({ nodeId, attributeId: AttributeIds.EventNotifier },
      { samplingInterval: 0, discardOldest: false, queueSize: 1000, filter: constructEventFilter(fields) }, TimestampsToReturn.Both);
    item.on("changed", (eventFields) => {
      try {
        const [message, severity, messageId, localized, category, args] = eventFields.map((f) => f.value);
        say({ event: true, message: message && message.text, severity, messageId,
          localized: Array.from(localized || []).filter((l) => l).map((l) => ({ locale: l.locale, text: l.text })),
          category,
          arguments: Array.from(args || []).filter((a) => a).map((a) => ({
            name: a.name, dataType: a.dataType && a.dataType.toString(), valueRank: a.valueRank,
            unit: a.description && a.description.text })) });
      } catch (err) {
        say({ event: true, error: String(err), raw: eventFields.map((f) => String(f.value)) });
      }
    });
    item.on("err", (err) => say({ event: true, error: String(err) }));
  }
  return { ok: true };
}

async function call(cmd) {
  const objectId = await resolve(cmd.object);
  const methodId = await resolve([...cmd.object, cmd.method]);
  const result = await session.call({ objectId, methodId,
    inputArguments: cmd.args.map((a) => ({ dataType: DataType.String, value: a })) });
  return { ok: result.statusCode.isGood(), status: result.statusCode.name,
    outputs: (result.outputArguments || []).map((o) => o.value) };
}

async function write(cmd) {
  const nodeId = await resolve(cmd.path);
  const status = await session.write({ nodeId, attributeId: AttributeIds.Value,
    value: { value: { dataType: DataType.Boolean, value: cmd.value } } });
  return { ok: status.isGood(), status: status.name };
}

async function quit() {
  if (subscription) await subscription.terminate();
  if (session) await session.close();
  if (client) await client.disconnect();
  return { ok: true };
}

const handlers = { connect, read, browse, methods, subscribe, call, write, quit };
const rl = readline.createInterface({ input: process.stdin });
let chain = Promise.resolve();
rl.on("line", (line) => {
  chain = chain.then(async () => {
    const cmd = JSON.parse(line);
    try {
      say({ reply: cmd.op, ...(await handlers[cmd.op](cmd)) });
    } catch (err) {
      say({ reply: cmd.op, ok: false, error: String(err && err.message ? err.message : err) });
    }
    if (cmd.op === "quit") process.exit(0);
  });
});
rl.on("close", () => { chain.then(() => process.exit(0)); });

/**
 * Concord's core: FIPA ACL, the agent runtime and its behaviours, the interaction protocols, the
 * layer SPI, the network and time. Its {@code internal} packages are Concord's own, exported only
 * to Concord's modules that build on them: an application cannot reach them.
 */
module io.concord.core {
    requires org.slf4j;

    exports io.concord.core.acl;
    exports io.concord.core.agent;
    exports io.concord.core.codec;
    exports io.concord.core.content;
    exports io.concord.core.layer;
    exports io.concord.core.net;
    exports io.concord.core.proto;
    exports io.concord.core.time;

    exports io.concord.core.agent.internal to io.concord.layers;
    exports io.concord.core.net.internal to io.concord.layers;
    exports io.concord.core.time.internal to io.concord.layers, io.concord.jade, io.concord.testkit;

    uses io.concord.core.layer.StackProvider;
}

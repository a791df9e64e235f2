package io.concord.layers.platform;

import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * The platform's protocol words as types: one record per word, {@link Lines} their only codec
 * ({@code docs/wire-format.md}, "Platform messages"). A message is decoded once, checked as it is
 * decoded (parameters present and numeric, pages in range, the sender's own entry first where the
 * word carries it), and handed to a {@link Handler} by its type.
 */
sealed interface PlatformMessage {

    /** The content as it goes on the wire. */
    String encode();

    /** Hands this message to the handler's method for its type. */
    void to(Handler h, AclMessage m);

    /** One method per word; by default a word is ignored. */
    interface Handler {
        default void onWhoIsContainer(WhoIsContainer w, AclMessage m) { }
        default void onContainerIs(ContainerIs c, AclMessage m) { }
        default void onSeeking(Seeking s, AclMessage m) { }
        default void onJoin(Join j, AclMessage m) { }
        default void onJoined(Joined j, AclMessage m) { }
        default void onLal(LalPage p, AclMessage m) { }
        default void onLalDelta(LalDelta d, AclMessage m) { }
        default void onHeld(Held h, AclMessage m) { }
        default void onAlive(Alive a, AclMessage m) { }
        default void onAgentInfoRequest(AgentInfoRequest r, AclMessage m) { }
        default void onAgentInfo(AgentInfo i, AclMessage m) { }
        default void onLeave(Leave l, AclMessage m) { }
        default void onLalRequest(LalRequest r, AclMessage m) { }
        default void onLalCopy(LalCopy c, AclMessage m) { }
        default void onGal(GalPage p, AclMessage m) { }

        default void onGalDelta(GalDelta d, AclMessage m) { }
        default void onRelayOut(RelayOut r, AclMessage m) { }
        default void onRelayIn(RelayIn r, AclMessage m) { }
        default void onAnnounce(Announce a, AclMessage m) { }
        default void onWhoIsFacilitator(WhoIsFacilitator w, AclMessage m) { }
        default void onIsFacilitator(IsFacilitator i, AclMessage m) { }
        default void onIsNotFacilitator(IsNotFacilitator i, AclMessage m) { }
        default void onGalUpdate(GalUpdate u, AclMessage m) { }
        default void onGalHeld(GalHeld h, AclMessage m) { }
        default void onUnknownSecret(UnknownSecret u, AclMessage m) { }
        default void onContactMe(ContactMe c, AclMessage m) { }
    }

    /**
     * One page of a list: its index, the count of pages of its version, and its entry lines (the
     * text after the command line). Entries are parsed when a page is decoded; a page made to be
     * sent carries only its text.
     */
    record Page(int index, int count, String body, List<AgentEntry> entries) {
        static Page of(int index, int count, String body) {
            return new Page(index, count, body, List.of());
        }

        static Page decode(Lines.Content c, String text, String what) {
            int page = (int) c.longParam("page");
            int n = (int) c.longParam("pages");
            if (n < 1 || n > 10_000 || page < 0 || page >= n) {
                throw new IllegalArgumentException("a bad " + what + " page " + page + " of " + n);
            }
            return new Page(page, n, body(text), c.entries());
        }

        static String body(String text) {
            int nl = text.indexOf('\n');
            return nl < 0 ? "" : text.substring(nl + 1);
        }
    }

    // ---- discovery and election (concord-discovery) ------------------------------------------

    /** QUERY-REF to whoever holds a port: who is container? Carries the asker's entry. */
    record WhoIsContainer(long round, AgentEntry asker) implements PlatformMessage {
        public String encode() {
            return Lines.content("who-is-container", Lines.params("round", round), List.of(asker));
        }

        public void to(Handler h, AclMessage m) {
            h.onWhoIsContainer(this, m);
        }
    }

    /**
     * A container claim: the answer to who-is-container, an announcement, a redirection to a better
     * one. {@code by} is the sender's entry when it is not the container itself.
     */
    record ContainerIs(long term, AgentEntry container, AgentEntry by) implements PlatformMessage {
        public String encode() {
            return Lines.content("container", Lines.params("term", term), by == null ? List.of(container) : List.of(container, by));
        }

        public void to(Handler h, AclMessage m) {
            h.onContainerIs(this, m);
        }
    }

    /** The answer of an agent that knows no container either. */
    record Seeking(long round, long term, AgentEntry by) implements PlatformMessage {
        public String encode() {
            return Lines.content("seeking", Lines.params("round", round, "term", term), List.of(by));
        }

        public void to(Handler h, AclMessage m) {
            h.onSeeking(this, m);
        }
    }

    // ---- the LAL (concord-lal) -------------------------------------------------------------------

    /** INFORM-REF to a container: register me. */
    record Join(long term, AgentEntry by) implements PlatformMessage {
        public String encode() {
            return Lines.content("join", Lines.params("term", term), List.of(by));
        }

        public void to(Handler h, AclMessage m) {
            h.onJoin(this, m);
        }
    }

    /** CONFIRM of a join, with the period and timeout the container computed from the agent count. */
    record Joined(long term, long period, long timeout, AgentEntry by) implements PlatformMessage {
        public String encode() {
            return Lines.content("joined", Lines.params("term", term, "period", period, "timeout", timeout), List.of(by));
        }

        public void to(Handler h, AclMessage m) {
            h.onJoined(this, m);
        }
    }

    /** One page of the LAL, versioned by (term, container, seq). */
    record LalPage(long term, long seq, long period, long timeout, Page page) implements PlatformMessage {
        public String encode() {
            return Lines.content("lal", Lines.params("term", term, "seq", seq, "page", page.index(), "pages", page.count(),
                    "period", period, "timeout", timeout), List.of()) + "\n" + page.body();
        }

        public void to(Handler h, AclMessage m) {
            h.onLal(this, m);
        }
    }

    /**
     * A page of what changed in the LAL from version {@code from} to {@code seq} (of this term):
     * the first {@code removed} entries of all its pages together are removed, the others added or
     * changed. A member holding version {@code from} applies it and confirms; any other ignores it,
     * and its next confirmation shows its container that it needs the whole list.
     */
    record LalDelta(long term, long from, long seq, long period, long timeout, int removed, Page page) implements PlatformMessage {
        public String encode() {
            String head = Lines.content("lal-delta", Lines.params("term", term, "from", from, "seq", seq, "removed", removed,
                    "page", page.index(), "pages", page.count(), "period", period, "timeout", timeout), List.of());
            return page.body().isEmpty() ? head : head + "\n" + page.body();
        }

        public void to(Handler h, AclMessage m) {
            h.onLalDelta(this, m);
        }
    }

    /**
     * A member's CONFIRM of the list version it holds: {@code lal-held} after a LAL, {@code alive-held}
     * (with the GAL version it holds and whose it is) after an alive.
     */
    record Held(boolean alive, long term, long seq, Long gseq, String gfrom) implements PlatformMessage {
        public String encode() {
            return alive ? Lines.content("alive-held", Lines.params("term", term, "seq", seq, "gseq", gseq,
                    "gfrom", gfrom == null ? "-" : gfrom), List.of())
                    : Lines.content("lal-held", Lines.params("term", term, "seq", seq), List.of());
        }

        public void to(Handler h, AclMessage m) {
            h.onHeld(this, m);
        }
    }

    /** INFORM each period from the container to every member. */
    record Alive(long term, long seq, long period, long timeout, AgentEntry by) implements PlatformMessage {
        public String encode() {
            return Lines.content("alive", Lines.params("term", term, "seq", seq, "period", period, "timeout", timeout), List.of(by));
        }

        public void to(Handler h, AclMessage m) {
            h.onAlive(this, m);
        }
    }

    /** REQUEST of a new container to every listed agent: your information (and I am container). */
    record AgentInfoRequest(long term, AgentEntry by) implements PlatformMessage {
        public String encode() {
            return Lines.content("agent-info", Lines.params("term", term), List.of(by));
        }

        public void to(Handler h, AclMessage m) {
            h.onAgentInfoRequest(this, m);
        }
    }

    /** The INFORM answering it: the agent's own entry. */
    record AgentInfo(long term, List<AgentEntry> entries) implements PlatformMessage {
        public String encode() {
            return Lines.content("agent-info", Lines.params("term", term), entries);
        }

        public void to(Handler h, AclMessage m) {
            h.onAgentInfo(this, m);
        }
    }

    /** An agent that stops says so (a container to all, a member to its container). */
    record Leave(long term) implements PlatformMessage {
        public String encode() {
            return Lines.content("leave", Lines.params("term", term), List.of());
        }

        public void to(Handler h, AclMessage m) {
            h.onLeave(this, m);
        }
    }

    /** After failed joins: a known agent is asked for the last valid LAL it holds. */
    record LalRequest(long term, AgentEntry by) implements PlatformMessage {
        public String encode() {
            return Lines.content("lal-request", Lines.params("term", term), List.of(by));
        }

        public void to(Handler h, AclMessage m) {
            h.onLalRequest(this, m);
        }
    }

    /** A page of that copy, naming the container its holder follows ("" if none). */
    record LalCopy(long term, long seq, String container, Page page) implements PlatformMessage {
        public String encode() {
            return Lines.content("lal-copy", Lines.params("term", term, "seq", seq, "page", page.index(),
                    "pages", page.count(), "container", container), List.of()) + "\n" + page.body();
        }

        public void to(Handler h, AclMessage m) {
            h.onLalCopy(this, m);
        }
    }

    /** A page of the Global Agent List from an agent's container. */
    record GalPage(long term, long gseq, Page page) implements PlatformMessage {
        public String encode() {
            String head = Lines.content("gal", Lines.params("term", term, "gseq", gseq, "page", page.index(),
                    "pages", page.count()), List.of());
            // An empty GAL is a page without entry lines.
            return page.body().isEmpty() ? head : head + "\n" + page.body();
        }

        public void to(Handler h, AclMessage m) {
            h.onGal(this, m);
        }
    }

    /**
     * A page of what changed in the Global Agent List from version {@code from} to {@code gseq}:
     * the first {@code removed} entries of all its pages together are removed from the list, the
     * others added or changed. A member holding version {@code from} applies it; any other waits
     * for the whole list, which its container sends when the member's confirmation shows it behind.
     */
    record GalDelta(long term, long from, long gseq, int removed, Page page) implements PlatformMessage {
        public String encode() {
            String head = Lines.content("gal-delta", Lines.params("term", term, "from", from, "gseq", gseq, "removed", removed,
                    "page", page.index(), "pages", page.count()), List.of());
            return page.body().isEmpty() ? head : head + "\n" + page.body();
        }

        public void to(Handler h, AclMessage m) {
            h.onGalDelta(this, m);
        }
    }

    // ---- the gateway relay (concord-services) --------------------------------------------------

    /** A member's message to a foreign agent, for its container's gateway to carry out. */
    record RelayOut(String receiver, String addresses, String acl) implements PlatformMessage {
        public String encode() {
            return Lines.content("relay-out", Lines.params("receiver", receiver, "addresses", addresses), List.of()) + "\n" + acl;
        }

        public void to(Handler h, AclMessage m) {
            h.onRelayOut(this, m);
        }
    }

    /** A foreign agent's message, relayed by the container to the member it is for. */
    record RelayIn(String receiver, String acl) implements PlatformMessage {
        public String encode() {
            return Lines.content("relay-in", Lines.params("receiver", receiver), List.of()) + "\n" + acl;
        }

        public void to(Handler h, AclMessage m) {
            h.onRelayIn(this, m);
        }
    }

    // ---- containers of other hosts (concord-network) -------------------------------------------

    /** A container's announcement, by broadcast and to its seeds, with the facilitators it knows. */
    record Announce(long term, String host, long seq, AgentEntry by, List<AgentEntry> known) implements PlatformMessage {
        public String encode() {
            List<AgentEntry> all = new ArrayList<>(known.size() + 1);
            all.add(by);
            all.addAll(known);
            return Lines.content("announce", Lines.params("term", term, "host", host, "seq", seq), all);
        }

        public void to(Handler h, AclMessage m) {
            h.onAnnounce(this, m);
        }
    }

    /** First contact between two containers: the opener's secret. */
    record WhoIsFacilitator(String secret, long term, String host, AgentEntry by) implements PlatformMessage {
        public String encode() {
            return Lines.content("who-is-facilitator", Lines.params("secret", secret, "term", term, "host", host), List.of(by));
        }

        public void to(Handler h, AclMessage m) {
            h.onWhoIsFacilitator(this, m);
        }
    }

    record IsFacilitator(String secret, long term, String host, AgentEntry by) implements PlatformMessage {
        public String encode() {
            return Lines.content("is-facilitator", Lines.params("secret", secret, "term", term, "host", host), List.of(by));
        }

        public void to(Handler h, AclMessage m) {
            h.onIsFacilitator(this, m);
        }
    }

    record IsNotFacilitator() implements PlatformMessage {
        public String encode() {
            return Lines.content("is-not-facilitator", Lines.params(), List.of());
        }

        public void to(Handler h, AclMessage m) {
            h.onIsNotFacilitator(this, m);
        }
    }

    /** A page of a host's LAL for another host's container, with the secret agreed between them. */
    record GalUpdate(String secret, long term, long seq, Page page) implements PlatformMessage {
        public String encode() {
            return Lines.content("gal-update", Lines.params("secret", secret, "term", term, "seq", seq, "page", page.index(),
                    "pages", page.count()), List.of()) + "\n" + page.body();
        }

        public void to(Handler h, AclMessage m) {
            h.onGalUpdate(this, m);
        }
    }

    /** The CONFIRM of the sender's list version this container now holds. */
    record GalHeld(String secret, long term, long seq) implements PlatformMessage {
        public String encode() {
            return Lines.content("gal-held", Lines.params("secret", secret, "term", term, "seq", seq), List.of());
        }

        public void to(Handler h, AclMessage m) {
            h.onGalHeld(this, m);
        }
    }

    record UnknownSecret() implements PlatformMessage {
        public String encode() {
            return Lines.content("unknown-secret", Lines.params(), List.of());
        }

        public void to(Handler h, AclMessage m) {
            h.onUnknownSecret(this, m);
        }
    }

    /** Asks a facilitator with a smaller name, which opens contacts, to open one. */
    record ContactMe(long term, String host, AgentEntry by) implements PlatformMessage {
        public String encode() {
            return Lines.content("contact-me", Lines.params("term", term, "host", host), List.of(by));
        }

        public void to(Handler h, AclMessage m) {
            h.onContactMe(this, m);
        }
    }

    /** The words that may come in a frame for any agent: asking a port, the answers, an announcement. */
    static boolean discovery(PlatformMessage p) {
        return p instanceof WhoIsContainer || p instanceof ContainerIs || p instanceof Seeking
                || p instanceof LalRequest || p instanceof Announce;
    }

    /**
     * Decodes a platform message's content.
     *
     * @throws IllegalArgumentException saying what is wrong: an unknown word, a missing or bad
     *     parameter, a page out of range, a missing sender's entry
     */
    static PlatformMessage decode(AclMessage m) {
        String text = m.getContent();
        if (text != null && (text.startsWith("relay-out ") || text.startsWith("relay-in "))) {
            int nl = text.indexOf('\n');
            if (nl < 0) {
                throw new IllegalArgumentException("a relayed message without its ACL part");
            }
            Map<String, String> p = Lines.parse(text.substring(0, nl)).params();
            String acl = text.substring(nl + 1);
            if (text.startsWith("relay-in ")) {
                return new RelayIn(p.getOrDefault("receiver", ""), acl);
            }
            String receiver = p.get("receiver");
            if (receiver == null) {
                throw new IllegalArgumentException("a relay without receiver=");
            }
            return new RelayOut(receiver, p.getOrDefault("addresses", ""), acl);
        }
        Lines.Content c = Lines.parse(text);
        Map<String, String> p = c.params();
        return switch (c.command()) {
            case "who-is-container" -> new WhoIsContainer(optLong(c, "round"), c.senderEntry(m));
            case "container" -> {
                long term = c.longParam("term");
                if (c.entries().isEmpty()) {
                    throw new IllegalArgumentException("a container message must carry the container's entry");
                }
                yield new ContainerIs(term, c.entries().get(0), c.spokenBy(c.entries().size() > 1 ? c.entries().get(1) : null, m));
            }
            case "seeking" -> {
                if (c.entries().size() != 1) {
                    throw new IllegalArgumentException("a seeking reply carries exactly its sender's entry");
                }
                yield new Seeking(optLong(c, "round"), optLong(c, "term"), c.senderEntry(m));
            }
            case "join" -> new Join(optLong(c, "term"), c.senderEntry(m));
            case "joined" -> new Joined(c.longParam("term"), c.longParam("period"), c.longParam("timeout"), c.senderEntry(m));
            case "lal" -> new LalPage(c.longParam("term"), c.longParam("seq"), c.longParam("period"), c.longParam("timeout"),
                    Page.decode(c, text, "LAL"));
            case "lal-delta" -> new LalDelta(c.longParam("term"), c.longParam("from"), c.longParam("seq"), c.longParam("period"),
                    c.longParam("timeout"), (int) Math.max(0, Math.min(Integer.MAX_VALUE, optLong(c, "removed"))),
                    Page.decode(c, text, "LAL change"));
            case "lal-held" -> new Held(false, c.longParam("term"), c.longParam("seq"), null, null);
            case "alive-held" -> new Held(true, c.longParam("term"), c.longParam("seq"),
                    p.containsKey("gseq") ? c.longParam("gseq") : null, p.get("gfrom"));
            case "alive" -> new Alive(c.longParam("term"), c.longParam("seq"), c.longParam("period"), c.longParam("timeout"),
                    c.senderEntry(m));
            case "agent-info" -> m.getPerformative() == Performative.REQUEST
                    ? new AgentInfoRequest(c.longParam("term"), c.senderEntry(m))
                    : new AgentInfo(optLong(c, "term"), c.entries());
            case "leave" -> new Leave(optLong(c, "term"));
            case "lal-request" -> new LalRequest(optLong(c, "term"), c.entries().isEmpty() ? null : c.senderEntry(m));
            case "lal-copy" -> new LalCopy(optLong(c, "term"), optLong(c, "seq"), p.getOrDefault("container", ""),
                    new Page((int) optLong(c, "page"), (int) Math.max(1, optLong(c, "pages")), Page.body(text), c.entries()));
            case "gal" -> new GalPage(optLong(c, "term"), c.longParam("gseq"), Page.decode(c, text, "GAL"));
            case "gal-delta" -> new GalDelta(optLong(c, "term"), c.longParam("from"), c.longParam("gseq"),
                    (int) Math.max(0, Math.min(Integer.MAX_VALUE, optLong(c, "removed"))), Page.decode(c, text, "GAL change"));
            case "announce" -> new Announce(c.longParam("term"), c.param("host"), optLong(c, "seq"), c.senderEntry(m),
                    c.entries().subList(1, c.entries().size()));
            case "who-is-facilitator" -> new WhoIsFacilitator(c.param("secret"), c.longParam("term"), c.param("host"),
                    c.senderEntry(m));
            case "is-facilitator" -> new IsFacilitator(c.param("secret"), optLong(c, "term"), p.getOrDefault("host", ""),
                    c.entries().isEmpty() ? null : c.senderEntry(m));
            case "is-not-facilitator" -> new IsNotFacilitator();
            case "gal-update" -> new GalUpdate(p.get("secret"), c.longParam("term"), c.longParam("seq"),
                    Page.decode(c, text, "list"));
            case "gal-held" -> new GalHeld(p.get("secret"), c.longParam("term"), c.longParam("seq"));
            case "unknown-secret" -> new UnknownSecret();
            case "contact-me" -> new ContactMe(c.longParam("term"), c.param("host"), c.senderEntry(m));
            default -> throw new IllegalArgumentException("unknown platform command '" + c.command() + "'");
        };
    }

    private static long optLong(Lines.Content c, String key) {
        return c.params().containsKey(key) ? c.longParam(key) : 0;
    }
}

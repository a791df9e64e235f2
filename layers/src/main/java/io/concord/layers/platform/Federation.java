package io.concord.layers.platform;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.net.Address;
import io.concord.core.net.Endpoint;
import io.concord.core.net.internal.Neighbourhood;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;

/**
 * What a container does with the containers of other hosts (dissertation fig. 5.12): it announces
 * itself by broadcast and to its seeds; on first contact the two agree a secret (REQUEST
 * who-is-facilitator with a random 128-bit secret, INFORM is-facilitator), then each sends its LAL
 * to the other with that secret, and again whenever it changes (INFORM-REF gal-update, CONFIRM
 * gal-held). An update without the right secret is discarded and counted ({@code bad-secret}).
 * The other hosts' lists make the Global Agent List; their containers the Facilitator Agent List.
 * A host not heard for the timeout leaves both; a host whose container changed is taken over by
 * its new container, whose announcement replaces the old one.
 */
final class Federation implements PlatformMessage.Handler {
    /**
     * Other hosts' containers known at most. Announcements name hosts second hand, and anyone with
     * the platform key can announce: a new one past the limit takes the place of one never
     * contacted (heard of longest ago), and is refused if every one known is in contact.
     */
    static final int MAX_FACILITATORS = 256;

    /** One facilitator: another host's container. */
    static final class Facilitator {
        AgentEntry entry;
        final String host;
        String secret;
        boolean contacted;
        long term;
        long seq = -1;
        List<AgentEntry> agents = List.of();
        long lastHeardNs;
        long contactTimer = -1;
        int contactAttempts;
        long heldSeq = -1;
        long heldTerm = -1;
        final PageAssembler pages = new PageAssembler();

        Facilitator(AgentEntry entry, String host) {
            this.entry = entry;
            this.host = host;
        }
    }

    /** What the federation needs of its agent beyond the context: its lists, its role, its sockets. */
    interface Host {
        List<String> lalPages();

        long term();

        long lalSequence();

        /** The facilitators' lists changed: the GAL is to be recomputed. */
        void globalChanged();

        /** A container of this same host announced itself: the better one stays container. */
        void contest(AgentEntry other, long term);
    }

    private final PlatformContext layer;
    private final Host agent;
    private final Neighbourhood around;
    private final NetworkConfig config;
    private final Map<String, Facilitator> fal = new TreeMap<>();
    private Endpoint listener;
    private long announcements;
    /** The announcements that carry the facilitators in contact: one in this many. */
    static final int KNOWN_EVERY = 4;
    private long announceTimer = -1;
    private long announceDueNs;
    /** Announcements in a row made while this container knew no other host's. */
    private int alone;
    /** A container alone announces at its period 4 times, then each 4 at twice the wait, up to this many periods. */
    static final int ALONE_MAX_PERIODS = 4;
    /**
     * The wait before looking again when there was nobody to announce to: no broadcast address
     * (bound to loopback), no seed, no other host's container known. One that contacts this one
     * is known at once, and the announcements go at the period again.
     */
    static final long NOBODY_TO_TELL_MS = 10_000;
    private boolean running;

    /** @param around the node's neighbourhood: its shared listener and broadcast addresses ({@code null}: none) */
    Federation(PlatformContext ctx, NetworkConfig config, Neighbourhood around, Host agent) {
        this.layer = ctx;
        this.config = config;
        this.around = around;
        this.agent = agent;
    }

    /** The names of the facilitators in contact. */
    List<String> contacted() {
        List<String> out = new ArrayList<>();
        for (Facilitator f : fal.values()) {
            if (f.contacted) {
                out.add(f.entry.name());
            }
        }
        return out;
    }

    /** The facilitators this container knows, by name. */
    Map<String, Facilitator> facilitators() {
        return fal;
    }

    /** Starts listening and announcing: this agent became its host's container. */
    void start() {
        if (running) {
            return;
        }
        running = true;
        alone = 0;
        listener = around == null ? null : around.openListener(config.discoveryPort());
        layer.trace("network", listener == null ? "cannot listen on the discovery port " + config.discoveryPort()
                + " (announcing only)" : "listening on the discovery port " + config.discoveryPort());
        announce();
    }

    /** Stops: this agent is no longer container (or stops). */
    void stop() {
        if (!running) {
            return;
        }
        running = false;
        announceTimer = layer.cancel(announceTimer);
        for (Facilitator f : fal.values()) {
            f.contactTimer = layer.cancel(f.contactTimer);
        }
        fal.clear();
        if (listener != null) {
            listener.close();
            listener = null;
        }
    }

    boolean running() {
        return running;
    }

    private String ownHost() {
        Address a = layer.selfEntry().transportAddress();
        return a == null ? "" : a.host();
    }

    private void announce() {
        announceTimer = -1;
        if (!running) {
            return;
        }
        // The facilitators in contact ride along: where only seeds connect the hosts, each learns of
        // the others through the ones it knows. Every fourth announcement only: each goes to every
        // host, so with all of them in every one, H hosts sent H entries to H hosts four times a
        // second (at 50 hosts, 1.5 kB per agent per maintenance cycle, the one term that grew).
        List<AgentEntry> known = new ArrayList<>();
        known.add(layer.selfEntry());
        if (announcements++ % KNOWN_EVERY == 0) {
            for (Facilitator f : fal.values()) {
                if (f.contacted) {
                    known.add(f.entry);
                }
            }
        }
        PlatformMessage content = new PlatformMessage.Announce(agent.term(), ownHost(), agent.lalSequence(), known.get(0),
                known.subList(1, known.size()));
        List<AID> to = new ArrayList<>();
        if (config.broadcast()) {
            for (String b : around == null ? List.<String>of() : around.broadcastAddresses()) {
                to.add(layer.anyAt(new Address(b, config.discoveryPort())));
            }
        }
        for (Address s : config.seeds()) {
            to.add(layer.anyAt(s));
        }
        for (Facilitator f : fal.values()) {
            to.add(f.entry.aid());
        }
        for (AID a : to) {
            layer.send(Performative.INFORM, Protocol.P_NETWORK, a, content);
        }
        // Lists not yet confirmed go again: distribution heals itself under loss.
        for (Facilitator f : fal.values()) {
            if (f.contacted && (f.heldSeq != agent.lalSequence() || f.heldTerm != agent.term())) {
                sendLal(f);
            }
        }
        expire();
        long wait = to.isEmpty() ? NOBODY_TO_TELL_MS : nextAnnouncementMs();
        announceDueNs = layer.nowNs() + wait * 1_000_000L;
        announceTimer = layer.after(wait, this::announce);
    }

    /**
     * The wait before the next announcement: the period while another host's container is known
     * (it takes this host for gone after a few missed ones); alone, longer and longer, up to
     * {@link #ALONE_MAX_PERIODS} periods. A newcomer announces at its period, and is heard at
     * once; so this only slows how fast two containers alone find each other after a partition,
     * and spares an idle host four broadcasts a second that nobody hears.
     */
    private long nextAnnouncementMs() {
        if (!fal.isEmpty()) {
            alone = 0;
            return config.announcePeriodMs();
        }
        int doublings = Math.min(alone++ / 4, Integer.numberOfTrailingZeros(ALONE_MAX_PERIODS));
        return config.announcePeriodMs() << doublings;
    }

    /** Hosts not heard for the timeout leave the lists. */
    private void expire() {
        long now = layer.nowNs();
        List<String> gone = new ArrayList<>();
        for (Facilitator f : fal.values()) {
            if (now - f.lastHeardNs > config.hostTimeoutMs() * 1_000_000L) {
                gone.add(f.entry.name());
            }
        }
        for (String g : gone) {
            Facilitator f = fal.remove(g);
            f.contactTimer = layer.cancel(f.contactTimer);
            layer.trace("host-gone", f.host + " (" + g + ") silent for " + config.hostTimeoutMs() + " ms");
        }
        if (!gone.isEmpty()) {
            agent.globalChanged();
        }
    }

    /** The other hosts' agents, without any name the LAL holds. */
    List<AgentEntry> globalAgents(Set<String> local) {
        List<AgentEntry> out = new ArrayList<>();
        Set<String> seen = new HashSet<>(local);
        for (Facilitator f : fal.values()) {
            for (AgentEntry e : f.agents) {
                if (seen.add(e.name())) {
                    out.add(e);
                }
            }
        }
        out.sort(Comparator.comparing(AgentEntry::name));
        return out;
    }

    /** The local LAL changed: send it to every facilitator in contact. */
    void localChanged() {
        if (!running) {
            return;
        }
        for (Facilitator f : fal.values()) {
            if (f.contacted) {
                sendLal(f);
            }
        }
    }

    private void sendLal(Facilitator f) {
        List<String> pages = agent.lalPages();
        for (int i = 0; i < pages.size(); i++) {
            layer.send(Performative.INFORM_REF, Protocol.P_NETWORK, f.entry.aid(), new PlatformMessage.GalUpdate(f.secret, agent.term(),
                    agent.lalSequence(), PlatformMessage.Page.of(i, pages.size(), pages.get(i))));
        }
    }

    @Override
    public void onAnnounce(PlatformMessage.Announce an, AclMessage m) {
        AgentEntry e = an.by();
        if (!running || e.name().equals(layer.selfEntry().name())) {
            return;
        }
        String host = an.host();
        if (host.equals(ownHost())) {
            agent.contest(e, an.term());
            return;
        }
        for (AgentEntry other : an.known()) {
            Address a = other.transportAddress();
            if (a != null && !fal.containsKey(other.name()) && !other.name().equals(layer.selfEntry().name())
                    && !a.host().equals(ownHost())) {
                learn(other, a.host(), 0);
            }
        }
        learn(e, host, an.term());
    }

    /** A facilitator heard (or heard of): known from now on; contacted by the smaller name. */
    private void learn(AgentEntry e, String host, long term) {
        Facilitator f = facilitator(e, host, term);
        if (f != null && !f.contacted && f.contactTimer < 0) {
            if (layer.selfEntry().name().compareTo(e.name()) < 0) {
                contact(f);
            } else {
                askForContact(e);
            }
        }
    }

    /**
     * The facilitator of that name, made (replacing its host's old one) if new; heard from now.
     * {@code null} if it is new and {@link #MAX_FACILITATORS} in contact are known already.
     */
    private Facilitator facilitator(AgentEntry e, String host, long term) {
        Facilitator f = fal.get(e.name());
        if (f == null) {
            replaceHost(host, e.name());
            if (fal.size() >= MAX_FACILITATORS && !forgetOneNeverContacted()) {
                layer.drop("facilitator-limit", MAX_FACILITATORS + " other hosts' containers are in contact already; "
                        + e.name() + " of host " + host + " is not taken");
                return null;
            }
            f = new Facilitator(e, host);
            f.term = term;
            fal.put(e.name(), f);
            layer.trace("facilitator", e.name() + " of host " + host);
            alone = 0;
            if (running && announceTimer >= 0 && announceDueNs - layer.nowNs() > config.announcePeriodMs() * 1_000_000L) {
                // It takes this host for gone after a few periods of silence: announce at the period again.
                announceTimer = layer.cancel(announceTimer);
                announceDueNs = layer.nowNs() + config.announcePeriodMs() * 1_000_000L;
                announceTimer = layer.after(config.announcePeriodMs(), this::announce);
            }
        }
        f.entry = e;
        f.lastHeardNs = layer.nowNs();
        return f;
    }

    /** Forgets the facilitator heard of longest ago that was never in contact; false if every one was. */
    private boolean forgetOneNeverContacted() {
        Facilitator oldest = null;
        for (Facilitator f : fal.values()) {
            if (!f.contacted && (oldest == null || f.lastHeardNs < oldest.lastHeardNs)) {
                oldest = f;
            }
        }
        if (oldest == null) {
            return false;
        }
        fal.remove(oldest.entry.name());
        oldest.contactTimer = layer.cancel(oldest.contactTimer);
        layer.drop("facilitator-limit", MAX_FACILITATORS + " other hosts' containers known: " + oldest.entry.name()
                + ", never in contact, is forgotten for a newer one");
        return true;
    }

    /** Asks a facilitator with a smaller name, which opens contacts, to open one with us. */
    private void askForContact(AgentEntry e) {
        layer.send(Performative.REQUEST, Protocol.P_NETWORK, e.aid(), new PlatformMessage.ContactMe(agent.term(), ownHost(), layer.selfEntry()));
    }

    /** A new container for a host replaces the old one: no stale container lingers. */
    private void replaceHost(String host, String newName) {
        List<String> stale = new ArrayList<>();
        for (Facilitator f : fal.values()) {
            if (f.host.equals(host) && !f.entry.name().equals(newName)) {
                stale.add(f.entry.name());
            }
        }
        for (String s : stale) {
            Facilitator old = fal.remove(s);
            old.contactTimer = layer.cancel(old.contactTimer);
            layer.trace("facilitator-replaced", s + " by " + newName + " on host " + host);
        }
        if (!stale.isEmpty()) {
            agent.globalChanged();
        }
    }

    private void contact(Facilitator f) {
        if (f.secret == null) {
            byte[] s = new byte[16];
            layer.secretBytes(s); // a SecureRandom's; the seed's in a simulation, which replays
            f.secret = HexFormat.of().formatHex(s);
        }
        f.contactAttempts++;
        layer.send(Performative.REQUEST, Protocol.P_NETWORK, f.entry.aid(),
                new PlatformMessage.WhoIsFacilitator(f.secret, agent.term(), ownHost(), layer.selfEntry()));
        f.contactTimer = layer.after(Math.max(50, config.announcePeriodMs() / 2), () -> {
            f.contactTimer = -1;
            if (!f.contacted && fal.get(f.entry.name()) == f && f.contactAttempts < 8) {
                contact(f);
            }
        });
    }

    @Override
    public void onWhoIsFacilitator(PlatformMessage.WhoIsFacilitator w, AclMessage m) {
        AgentEntry e = w.by();
        if (!running) {
            layer.sendQuietly(layer.reply(m, Performative.INFORM, new PlatformMessage.IsNotFacilitator()));
            return;
        }
        Facilitator f = facilitator(e, w.host(), w.term());
        if (f == null) {
            layer.sendQuietly(layer.reply(m, Performative.INFORM, new PlatformMessage.IsNotFacilitator()));
            return;
        }
        f.term = w.term();
        f.secret = w.secret();
        f.contacted = true;
        layer.sendQuietly(layer.reply(m, Performative.INFORM, new PlatformMessage.IsFacilitator(f.secret, agent.term(),
                ownHost(), layer.selfEntry())));
        sendLal(f);
    }

    @Override
    public void onIsFacilitator(PlatformMessage.IsFacilitator i, AclMessage m) {
        Facilitator f = fal.get(m.getSender().name());
        if (f == null || f.secret == null || !f.secret.equals(i.secret())) {
            layer.drop("bad-secret", m.getSender().name()
                    + " confirmed a contact with a secret this container did not offer");
            return;
        }
        f.contacted = true;
        f.lastHeardNs = layer.nowNs();
        f.contactTimer = layer.cancel(f.contactTimer);
        layer.trace("facilitator-contact", m.getSender().name());
        sendLal(f);
    }

    /** A facilitator with a larger name has no contact with us: open a new one. */
    @Override
    public void onContactMe(PlatformMessage.ContactMe c, AclMessage m) {
        AgentEntry e = c.by();
        if (!running || layer.selfEntry().name().compareTo(e.name()) >= 0) {
            return;
        }
        Facilitator f = facilitator(e, c.host(), c.term());
        if (f == null || f.contactTimer >= 0) {
            return; // a contact is under way
        }
        f.contacted = false;
        f.secret = null;
        f.seq = -1;
        f.contactAttempts = 0;
        contact(f);
    }

    /** The facilitator does not know our secret: contact it again (the smaller name opens). */
    @Override
    public void onUnknownSecret(PlatformMessage.UnknownSecret u, AclMessage m) {
        Facilitator f = fal.get(m.getSender().name());
        if (f == null || !running) {
            return;
        }
        f.contacted = false;
        f.secret = null;
        f.seq = -1;
        f.contactAttempts = 0;
        f.contactTimer = layer.cancel(f.contactTimer);
        if (layer.selfEntry().name().compareTo(f.entry.name()) < 0) {
            contact(f);
        } else {
            layer.send(Performative.INFORM, Protocol.P_NETWORK, f.entry.aid(),
                    new PlatformMessage.Announce(agent.term(), ownHost(), agent.lalSequence(), layer.selfEntry(), List.of()));
        }
    }

    @Override
    public void onIsNotFacilitator(PlatformMessage.IsNotFacilitator i, AclMessage m) {
        Facilitator f = fal.remove(m.getSender().name());
        if (f != null) {
            f.contactTimer = layer.cancel(f.contactTimer);
            agent.globalChanged();
        }
    }

    @Override
    public void onGalUpdate(PlatformMessage.GalUpdate u, AclMessage m) {
        Facilitator f = fal.get(m.getSender().name());
        if (f == null || !f.contacted || f.secret == null || !f.secret.equals(u.secret())) {
            layer.drop("bad-secret", "a list update from "
                    + m.getSender().name() + " without the secret agreed with it: discarded");
            layer.trace("gal-rejected", m.getSender().name());
            if (running) {
                // Perhaps it kept a contact this container forgot (it took that host for gone): say so,
                // and a new contact with a new secret follows.
                layer.sendQuietly(layer.reply(m, Performative.INFORM, new PlatformMessage.UnknownSecret()));
            }
            return;
        }
        long term = u.term();
        long seq = u.seq();
        f.lastHeardNs = layer.nowNs();
        if (term < f.term || (term == f.term && seq <= f.seq)) {
            ack(f, m);
            return;
        }
        List<AgentEntry> all = f.pages.add(term + "/" + seq, u.page());
        if (all == null) {
            return;
        }
        f.term = term;
        f.seq = seq;
        f.agents = List.copyOf(all);
        layer.trace("gal-applied", m.getSender().name() + " term=" + term + " seq=" + seq + " agents=" + all.size());
        ack(f, m);
        agent.globalChanged();
    }

    private void ack(Facilitator f, AclMessage m) {
        layer.sendQuietly(layer.reply(m, Performative.CONFIRM, new PlatformMessage.GalHeld(f.secret, f.term, f.seq)));
        // (term, seq) here are the sender's own list version, which this container now holds.
    }

    @Override
    public void onGalHeld(PlatformMessage.GalHeld h, AclMessage m) {
        Facilitator f = fal.get(m.getSender().name());
        if (f == null || f.secret == null || !f.secret.equals(h.secret())) {
            return;
        }
        f.lastHeardNs = layer.nowNs();
        f.heldSeq = h.seq();
        f.heldTerm = h.term();
    }
}

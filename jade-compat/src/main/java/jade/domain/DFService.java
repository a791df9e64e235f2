package jade.domain;

import io.concord.jadecompat.internal.AgentAccess;
import io.concord.jadecompat.internal.DfSl;
import io.concord.jadecompat.internal.Engine;
import io.concord.jadecompat.internal.Host;
import io.concord.layers.PlatformServices;
import io.concord.layers.platform.AgentEntry;
import jade.core.AID;
import jade.core.Agent;
import jade.lang.acl.ACLMessage;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.domain.FIPAAgentManagement.FailureException;
import jade.domain.FIPAAgentManagement.RefuseException;
import jade.domain.FIPAAgentManagement.SearchConstraints;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeoutException;
import java.util.function.Function;

/**
 * JADE's synchronous DF calls, over Concord's DF: each waits for the DF's answer on the calling
 * agent's thread, and works from {@code setup()} and {@code takeDown()}. Concord keeps an agent's
 * registration while it lives (it registers again after a container failover by itself).
 */
public class DFService {
    /** JADE's DF answers at most this many results when the search constraints give no limit. */
    static final int DEFAULT_MAX_RESULTS = 100;

    /** The agents (these objects, not their names: a new agent of the same name starts unregistered) that registered. */
    private static final Map<Agent, Boolean> REGISTERED = java.util.Collections.synchronizedMap(new java.util.WeakHashMap<>());

    private static final java.util.concurrent.atomic.AtomicLong SUBSCRIPTIONS = new java.util.concurrent.atomic.AtomicLong();

    /** Each registered agent's lease, as its registration stands now (a new register or modify replaces it). */
    private static final Map<Agent, Object> LEASES = java.util.Collections.synchronizedMap(new java.util.WeakHashMap<>());
    private static final java.util.concurrent.ScheduledExecutorService LEASE_TIMER =
            java.util.concurrent.Executors.newSingleThreadScheduledExecutor(r -> {
                Thread t = new Thread(r, "concord-jade-df-leases");
                t.setDaemon(true);
                return t;
            });

    public DFService() {
    }

    /** Registers the agent's services with the default DF; the description's name defaults to the agent's AID. */
    public static DFAgentDescription register(Agent a, DFAgentDescription dfd) throws FIPAException {
        return register(a, a.getDefaultDF(), dfd);
    }

    /** Registers with a DF: only the platform's own DF is supported. */
    public static DFAgentDescription register(Agent a, AID dfName, DFAgentDescription dfd) throws FIPAException {
        checkDf(a, dfName);
        AID who = ownName(a, dfd);
        if (REGISTERED.putIfAbsent(a, Boolean.TRUE) != null) {
            throw new FailureException("(already-registered)");
        }
        try {
            call(a, ps -> ps.modify(toConcord(dfd).toArray(io.concord.layers.platform.ServiceDescription[]::new)));
        } catch (FIPAException e) {
            REGISTERED.remove(a);
            throw e;
        }
        lease(a, dfd);
        dfd.setName(who);
        return dfd;
    }

    /**
     * The DF removes a registration whose lease time (if any) has passed, as JADE's DF does: the
     * agent is then unregistered (it may register again). A later register or modify replaces the lease.
     */
    private static void lease(Agent a, DFAgentDescription dfd) {
        Object token = new Object();
        LEASES.put(a, token);
        if (dfd.getLeaseTime() == null) {
            return;
        }
        long delay = Math.max(0, dfd.getLeaseTime().getTime() - System.currentTimeMillis());
        LEASE_TIMER.schedule(() -> {
            synchronized (LEASES) {
                if (LEASES.get(a) != token) {
                    return;
                }
                LEASES.remove(a);
            }
            if (REGISTERED.remove(a) != null) {
                try {
                    call(a, PlatformServices::deregister);
                } catch (FIPAException | RuntimeException e) {
                    // the agent has gone, and its registration with it
                    LEASES.remove(a);
                }
            }
        }, delay, java.util.concurrent.TimeUnit.MILLISECONDS);
    }

    public static void deregister(Agent a) throws FIPAException {
        deregister(a, a.getDefaultDF(), null);
    }

    public static void deregister(Agent a, DFAgentDescription dfd) throws FIPAException {
        deregister(a, a.getDefaultDF(), dfd);
    }

    public static void deregister(Agent a, AID dfName) throws FIPAException {
        deregister(a, dfName, null);
    }

    /** Removes the agent's registration; fails if it has none. */
    public static void deregister(Agent a, AID dfName, DFAgentDescription dfd) throws FIPAException {
        checkDf(a, dfName);
        if (dfd != null) {
            ownName(a, dfd);
        }
        if (REGISTERED.remove(a) == null) {
            throw new FailureException("(not-registered)");
        }
        LEASES.remove(a);
        call(a, PlatformServices::deregister);
    }

    public static DFAgentDescription modify(Agent a, DFAgentDescription dfd) throws FIPAException {
        return modify(a, a.getDefaultDF(), dfd);
    }

    /** Replaces the agent's registration; fails if it has none. */
    public static DFAgentDescription modify(Agent a, AID dfName, DFAgentDescription dfd) throws FIPAException {
        checkDf(a, dfName);
        AID who = ownName(a, dfd);
        if (!REGISTERED.containsKey(a)) {
            throw new FailureException("(not-registered)");
        }
        call(a, ps -> ps.modify(toConcord(dfd).toArray(io.concord.layers.platform.ServiceDescription[]::new)));
        lease(a, dfd);
        dfd.setName(who);
        return dfd;
    }

    public static DFAgentDescription[] search(Agent a, DFAgentDescription dfd) throws FIPAException {
        return search(a, a.getDefaultDF(), dfd, null);
    }

    public static DFAgentDescription[] search(Agent a, DFAgentDescription dfd, SearchConstraints constraints)
            throws FIPAException {
        return search(a, a.getDefaultDF(), dfd, constraints);
    }

    public static DFAgentDescription[] search(Agent a, AID dfName, DFAgentDescription dfd) throws FIPAException {
        return search(a, dfName, dfd, null);
    }

    /**
     * The agents whose registration matches the template: its name if set, and each of its
     * services (type, name, properties, protocols, ontologies, languages) matched by one of theirs.
     * At most {@code constraints.getMaxResults()} (-1: all; none given: 100, JADE's DF default).
     */
    public static DFAgentDescription[] search(Agent a, AID dfName, DFAgentDescription dfd, SearchConstraints constraints)
            throws FIPAException {
        checkDf(a, dfName);
        List<io.concord.layers.platform.ServiceDescription> templates = toConcord(dfd);
        io.concord.layers.platform.ServiceDescription first = templates.isEmpty()
                ? new io.concord.layers.platform.ServiceDescription(null, null, Map.of(), List.of(), List.of(), List.of())
                : templates.get(0);
        List<AgentEntry> found = call(a, ps -> ps.search(first));
        long max = constraints == null || constraints.getMaxResults() == null ? DEFAULT_MAX_RESULTS
                : constraints.getMaxResults();
        List<DFAgentDescription> result = new ArrayList<>();
        for (AgentEntry e : found) {
            if (max >= 0 && result.size() >= max) {
                break;
            }
            if (dfd.getName() != null && !dfd.getName().getName().equalsIgnoreCase(io.concord.jadecompat.internal.Names.decode(e.name()))) {
                continue;
            }
            if (!templates.isEmpty() && !io.concord.layers.platform.ServiceDescription.offersAll(e.services(), templates)) {
                continue;
            }
            result.add(toJade(e));
        }
        return result.toArray(new DFAgentDescription[0]);
    }

    /**
     * Searches until at least one agent is found or {@code timeout} ms have passed, as JADE's
     * {@code searchUntilFound} does (here by asking again every 100 ms).
     */
    public static DFAgentDescription[] searchUntilFound(Agent a, AID dfName, DFAgentDescription dfd,
                                                        SearchConstraints constraints, long timeout) throws FIPAException {
        long deadline = Engine.nowMs() + timeout;
        while (true) {
            DFAgentDescription[] r = search(a, dfName, dfd, constraints);
            if (r.length > 0 || Engine.nowMs() >= deadline) {
                return r.length > 0 ? r : null;
            }
            a.doWait(Math.min(100, Math.max(1, deadline - Engine.nowMs())));
        }
    }

    private static void checkDf(Agent a, AID dfName) throws FIPAException {
        if (dfName != null && !dfName.equals(a.getDefaultDF())) {
            throw new RefuseException("(unsupported-function federated-df) concord-jade talks only to the platform's own DF, "
                    + a.getDefaultDF().getName() + ", not " + dfName.getName());
        }
    }

    private static AID ownName(Agent a, DFAgentDescription dfd) throws FIPAException {
        AID who = dfd == null || dfd.getName() == null ? a.getAID() : dfd.getName();
        if (!who.equals(a.getAID())) {
            throw new RefuseException("(unauthorised) concord-jade registers an agent's own services only, not "
                    + who.getName() + "'s");
        }
        return a.getAID();
    }

    private static <T> T call(Agent a, Function<PlatformServices, CompletableFuture<T>> request) throws FIPAException {
        Host host = AgentAccess.get().host(a);
        Engine engine = AgentAccess.get().engine(a);
        if (host == null || engine == null) {
            throw new FailureException("(internal-error) the agent has not started");
        }
        try {
            return engine.call(host, request);
        } catch (ExecutionException e) {
            throw new FailureException("(internal-error \"" + e.getCause().getMessage() + "\")");
        } catch (TimeoutException e) {
            throw new FailureException("(internal-error \"no answer from the DF in " + Engine.DF_TIMEOUT_MS + " ms\")");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new FailureException("(internal-error interrupted)");
        }
    }

    static List<io.concord.layers.platform.ServiceDescription> toConcord(DFAgentDescription dfd) {
        return DfSl.toConcord(dfd);
    }

    static DFAgentDescription toJade(AgentEntry e) {
        return DfSl.toJade(e);
    }

    /**
     * A SUBSCRIBE to the DF for the agents matching the template, as JADE writes it (FIPA-subscribe,
     * {@code fipa-sl}, FIPA-Agent-Management, a conversation id of its own): send it, or give it to a
     * {@link jade.proto.SubscriptionInitiator}. The DF answers at once with the registrations that
     * match, if any, then with an INFORM at each registration, change or deregistration among them
     * (a deregistered agent comes with no services); {@link #decodeNotification} reads them. Here
     * the DF matches on the template's first service.
     */
    public static ACLMessage createSubscriptionMessage(Agent a, AID dfName, DFAgentDescription template,
                                                       SearchConstraints constraints) {
        AID df = dfName == null ? a.getDefaultDF() : dfName;
        ACLMessage m = new ACLMessage(ACLMessage.SUBSCRIBE);
        m.setSender(a.getAID());
        m.addReceiver(df);
        m.setProtocol(FIPANames.InteractionProtocol.FIPA_SUBSCRIBE);
        m.setLanguage(FIPANames.ContentLanguage.FIPA_SL);
        m.setOntology(FIPANames.Ontology.SL0_ONTOLOGY);
        long n = SUBSCRIPTIONS.incrementAndGet();
        m.setReplyWith("rw-" + a.getName() + Engine.nowMs() + "-" + n);
        m.setConversationId("conv-" + a.getName() + Engine.nowMs() + "-" + n);
        m.setContent(DfSl.subscription(df, template == null ? new DFAgentDescription() : template, constraints));
        return m;
    }

    /** The descriptions a DF notification carries (its content); a deregistered agent's has no services. */
    public static DFAgentDescription[] decodeNotification(String content) throws FIPAException {
        try {
            return DfSl.descriptions(content);
        } catch (RuntimeException e) {
            throw new FIPAException("not a DF notification: " + e.getMessage());
        }
    }
}

package io.concord.agents.proto;

import io.concord.agents.proto.WheelchairMessage.*;
import io.concord.core.acl.Performative;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.EnumSet;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.function.Function;

import static io.concord.core.acl.Performative.*;

/**
 * {@link WheelchairMessage}'s table of words: which record a word is under each performative, and
 * the readers of its typed fields. Package-private: agents use the records.
 */
final class Codec {
    private static final Map<Performative, Map<String, Function<Content, WheelchairMessage>>> READERS = new EnumMap<>(Performative.class);
    private static final Map<Class<?>, String> VERBS = new HashMap<>();
    private static final Map<Class<?>, Set<Performative>> UNDER = new HashMap<>();

    static {
        word(TransportCall.class, "transport", TransportCall::read, CFP);
        word(TransportRequest.class, "transport", TransportRequest::read, REQUEST, AGREE);
        word(Proposal.class, "proposal", Proposal::read, PROPOSE);
        word(Refused.class, "refuse", Refused::read, REFUSE);
        word(Award.class, "transport", Award::read, ACCEPT_PROPOSAL);
        word(Rejection.class, "transport", Rejection::read, REJECT_PROPOSAL);
        word(Withdrawal.class, "transport", Withdrawal::read, CANCEL);
        word(Done.class, "done", Done::read, INFORM);
        word(Failed.class, "failed", Failed::read, FAILURE);
        word(Paused.class, "paused", Paused::read, INFORM);
        word(Resumed.class, "resumed", Resumed::read, INFORM);
        word(Progress.class, "progress", Progress::read, INFORM);
        word(ResumeRequest.class, "resume", ResumeRequest::read, REQUEST);
        word(Resuming.class, "resuming", Resuming::read, INFORM);
        word(PlanRequest.class, "plan", PlanRequest::read, REQUEST);
        word(PlanAgreed.class, "plan", PlanAgreed::read, AGREE);
        word(Plan.class, "plan", Plan::read, INFORM_REF);
        word(NoRoute.class, "no-route", NoRoute::read, FAILURE);
        word(Blocked.class, "blocked", Blocked::read, INFORM);
        word(StateQuery.class, "state", StateQuery::read, SUBSCRIBE, REQUEST);
        word(DoorState.class, "state", DoorState::read, AGREE, INFORM);
        word(PassRequest.class, "pass", PassRequest::read, REQUEST);
        word(PassConfirmed.class, "pass", PassConfirmed::read, CONFIRM);
        word(OpenRequest.class, "open", OpenRequest::read, REQUEST);
        word(OpenQueued.class, "open", OpenQueued::read, AGREE);
        word(DoorOpen.class, "open", DoorOpen::read, INFORM);
        word(Failure.class, "failure", Failure::read, FAILURE);
        word(Passed.class, "passed", Passed::read, INFORM);
        word(Here.class, "here", Here::read, INFORM);
        word(Reserve.class, "reserve", Reserve::read, REQUEST);
        word(Granted.class, "granted", Granted::read, INFORM);
        word(Clear.class, "clear", Clear::read, INFORM);
        word(ReserveWaits.class, "reserve", ReserveWaits::read, AGREE);
        word(Release.class, "release", Release::read, INFORM);
        word(Idle.class, "idle", Idle::read, INFORM);
        word(MakeWay.class, "make-way", MakeWay::read, INFORM);
    }

    private Codec() {
    }

    private static void word(Class<? extends WheelchairMessage> kind, String verb, Function<Content, WheelchairMessage> read,
                             Performative... under) {
        VERBS.put(kind, verb);
        UNDER.put(kind, EnumSet.of(under[0], under));
        for (Performative p : under) {
            if (READERS.computeIfAbsent(p, x -> new HashMap<>()).put(verb, read) != null) {
                throw new IllegalStateException("two records for '" + verb + "' under " + p);
            }
        }
    }

    static String verb(Class<?> kind) {
        return VERBS.get(kind);
    }

    /** The performatives a kind is sent under. */
    static Set<Performative> under(Class<?> kind) {
        return UNDER.get(kind);
    }

    /** Every kind of message there is (for tests). */
    static Set<Class<?>> kinds() {
        return VERBS.keySet();
    }

    static WheelchairMessage decode(String text, Performative performative) {
        Content c;
        try {
            c = Content.parse(text);
        } catch (IllegalArgumentException e) {
            throw new Unreadable(e.getMessage());
        }
        Function<Content, WheelchairMessage> read = READERS.getOrDefault(performative, Map.of()).get(c.verb());
        if (read == null) {
            throw new UnknownWord(c.verb(), performative);
        }
        try {
            return read.apply(c);
        } catch (IllegalArgumentException e) {
            throw new BadField(e.getMessage());
        }
    }

    // ---- typed fields -----------------------------------------------------------------------------

    /** A list comma-separated, as it is written. */
    static String join(List<?> items) {
        StringBuilder b = new StringBuilder();
        for (Object o : items) {
            b.append(b.length() == 0 ? "" : ",").append(o);
        }
        return b.toString();
    }

    /** A list of node ids (empty if absent). */
    static List<Integer> nodes(Content c, String key) {
        List<Integer> out = new ArrayList<>();
        for (String s : c.list(key)) {
            try {
                out.add(Integer.parseInt(s));
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException(key + ": '" + s + "' is not a node id");
            }
        }
        return out;
    }

    /** A whole number, or null if absent. */
    static Integer optionalInt(Content c, String key) {
        return c.get(key) == null ? null : c.integer(key);
    }

    /** A proposal's other open proposals: {@code T1:177.4,T3:139.5} (seconds to a tenth). */
    static String pending(List<Proposal.Pending> pending) {
        List<String> items = new ArrayList<>();
        for (Proposal.Pending p : pending) {
            items.add(p.task() + ":" + String.format(Locale.ROOT, "%.1f", p.seconds()));
        }
        return join(items);
    }

    static List<Proposal.Pending> pending(Content c) {
        List<Proposal.Pending> out = new ArrayList<>();
        for (String item : c.list("pending")) {
            int colon = item.lastIndexOf(':');
            try {
                if (colon <= 0) {
                    throw new NumberFormatException();
                }
                out.add(new Proposal.Pending(item.substring(0, colon), Double.parseDouble(item.substring(colon + 1))));
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("pending: '" + item + "' is not task:seconds");
            }
        }
        return out;
    }

    /** Who resumes a paused task: {@code agent} or {@code operator}. */
    static String resumer(boolean agent) {
        return agent ? "agent" : "operator";
    }

    static boolean resumer(Content c) {
        String v = c.text("resume");
        if (!v.equals("agent") && !v.equals("operator")) {
            throw new IllegalArgumentException("field 'resume' must be agent or operator, got '" + v + "'");
        }
        return v.equals("agent");
    }
}

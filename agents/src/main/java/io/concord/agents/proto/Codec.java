package io.concord.agents.proto;

import io.concord.agents.proto.WheelchairMessage.*;
import io.concord.core.acl.Performative;
import io.concord.core.content.AbsCompound;
import io.concord.core.content.AbsObject;
import io.concord.core.content.BeanOntology;
import io.concord.core.content.ContentException;
import io.concord.core.content.Element;
import io.concord.core.content.SlCodec;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.EnumSet;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

import static io.concord.core.acl.Performative.*;

/**
 * {@link WheelchairMessage}'s ontology and codec: the records as a {@link BeanOntology} named
 * {@value Services#ONTOLOGY}, written and read in FIPA-SL, and under which performatives each is
 * sent. Package-private: agents use the records.
 */
final class Codec {
    private static final Map<Class<?>, String> VERBS = new HashMap<>();
    private static final Map<String, Class<?>> KINDS = new HashMap<>();
    private static final Map<Class<?>, Set<Performative>> UNDER = new HashMap<>();
    private static final SlCodec SL = new SlCodec();
    static final BeanOntology ONTOLOGY;

    static {
        under(TransportCall.class, CFP);
        under(TransportRequest.class, REQUEST, AGREE);
        under(Proposal.class, PROPOSE);
        under(Refused.class, REFUSE);
        under(Award.class, ACCEPT_PROPOSAL);
        under(Rejection.class, REJECT_PROPOSAL);
        under(Withdrawal.class, CANCEL);
        under(CancelRequest.class, REQUEST, AGREE);
        under(Done.class, INFORM);
        under(Failed.class, FAILURE);
        under(Paused.class, INFORM);
        under(Resumed.class, INFORM);
        under(Progress.class, INFORM);
        under(ResumeRequest.class, REQUEST);
        under(Resuming.class, INFORM);
        under(PlanRequest.class, REQUEST);
        under(PlanAgreed.class, AGREE);
        under(Plan.class, INFORM_REF);
        under(NoRoute.class, FAILURE);
        under(Blocked.class, INFORM);
        under(StateQuery.class, SUBSCRIBE, REQUEST);
        under(DoorState.class, AGREE, INFORM);
        under(PassRequest.class, REQUEST);
        under(PassConfirmed.class, CONFIRM);
        under(OpenRequest.class, REQUEST);
        under(OpenQueued.class, AGREE);
        under(DoorOpen.class, INFORM);
        under(Failure.class, FAILURE);
        under(Passed.class, INFORM);
        under(Here.class, INFORM);
        under(Reserve.class, REQUEST);
        under(Granted.class, INFORM);
        under(Clear.class, INFORM);
        under(ReserveWaits.class, AGREE);
        under(Release.class, INFORM);
        under(WaitEstimate.class, QUERY_REF, INFORM_REF);
        under(Idle.class, INFORM);
        under(MakeWay.class, INFORM);
        under(Stalled.class, INFORM);
        List<Class<?>> elements = new ArrayList<>(UNDER.keySet());
        elements.add(Proposal.Pending.class);
        elements.sort(java.util.Comparator.comparing(Class::getName));
        ONTOLOGY = new BeanOntology(Services.ONTOLOGY, elements.toArray(Class<?>[]::new));
    }

    private Codec() {
    }

    private static void under(Class<? extends WheelchairMessage> kind, Performative... under) {
        String verb = kind.getAnnotation(Element.class).name();
        VERBS.put(kind, verb);
        if (KINDS.put(verb, kind) != null) {
            throw new IllegalStateException("two records named " + verb);
        }
        UNDER.put(kind, EnumSet.of(under[0], under));
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

    /** True if the content starts with this opening, {@code ((name}, followed by a slot or the end of the element. */
    static boolean startsWith(String content, String open) {
        if (content == null || !content.startsWith(open)) {
            return false;
        }
        char next = content.length() > open.length() ? content.charAt(open.length()) : ' ';
        return next == ' ' || next == ')';
    }

    static String encode(WheelchairMessage w) {
        try {
            return SL.write(ONTOLOGY.toAbs(w));
        } catch (ContentException e) {
            throw new IllegalArgumentException(w.verb() + " cannot be written: " + e.reason(), e);
        }
    }

    static WheelchairMessage decode(String text, Performative performative) {
        if (text == null || text.isBlank()) {
            throw new Unreadable("empty content");
        }
        List<AbsObject> elements;
        try {
            elements = SL.read(text);
        } catch (ContentException e) {
            throw new Unreadable("content is not FIPA-SL (" + e.reason() + "); the wheelchair's contents are one element, "
                    + "such as ((transport-request :from 3 :to 9)): docs/wheelchair-protocol.md");
        }
        if (elements.size() != 1 || !(elements.get(0) instanceof AbsCompound element)) {
            throw new Unreadable("content must be one element, such as ((transport-request :from 3 :to 9)); got "
                    + elements.size() + " element(s)");
        }
        Class<?> kind = KINDS.get(element.name());
        if (kind == null || !UNDER.get(kind).contains(performative)) {
            throw new UnknownWord(element.name(), performative);
        }
        try {
            return (WheelchairMessage) ONTOLOGY.fromAbs(element);
        } catch (ContentException e) {
            throw new BadField(e.reason());
        } catch (IllegalArgumentException e) {
            throw new BadField(element.name() + ": " + e.getMessage());
        }
    }

    /** A list as a record keeps it: unmodifiable, empty when absent. */
    static <T> List<T> list(List<T> items) {
        return items == null ? List.of() : List.copyOf(items);
    }
}

package io.concord.layers.parser;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.net.Address;

import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Who belongs to the platform, for the parser layer's membership control and identification
 * procedure. The container layer keeps the real one (the agent lists); this interface lets a
 * static list or an open platform stand in until it does.
 */
public interface Membership {

    /** What membership says about a message's sender. */
    enum Verdict {
        /** A member, speaking from where it is known to be. */
        MEMBER,
        /** Not checked: discovery and join messages, which come before membership. */
        EXEMPT,
        /** Not a member. */
        UNKNOWN,
        /** Not a member yet, but joining: worth asking for the message again later. */
        PENDING,
        /** A member, but speaking from an address other than the one it is known at. */
        WRONG_SOURCE
    }

    /** Checks a message's sender and the transport address it came from. */
    Verdict check(AclMessage message, AID sender, Address source);

    /** Everyone is a member (closed networks, and platforms before the container layer). */
    static Membership open() {
        return (m, s, a) -> Verdict.MEMBER;
    }

    /** Ontology that marks the platform's own discovery and join messages. */
    String PLATFORM_ONTOLOGY = "concord-platform";

    /** A list kept by hand: name to address, plus names that are joining. */
    final class Static implements Membership {
        private final Map<AID, Address> members = new ConcurrentHashMap<>();
        private final Set<AID> pending = ConcurrentHashMap.newKeySet();

        public Static add(AID agent, Address at) {
            members.put(agent, at);
            pending.remove(agent);
            return this;
        }

        public Static remove(AID agent) {
            members.remove(agent);
            return this;
        }

        public Static joining(AID agent) {
            pending.add(agent);
            return this;
        }

        @Override
        public Verdict check(AclMessage message, AID sender, Address source) {
            if (PLATFORM_ONTOLOGY.equals(message.getOntology())) {
                return Verdict.EXEMPT;
            }
            Address known = members.get(sender);
            if (known == null) {
                return pending.contains(sender) ? Verdict.PENDING : Verdict.UNKNOWN;
            }
            return known.equals(source) ? Verdict.MEMBER : Verdict.WRONG_SOURCE;
        }
    }
}

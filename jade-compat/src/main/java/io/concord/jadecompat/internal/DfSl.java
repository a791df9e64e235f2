package io.concord.jadecompat.internal;

import io.concord.layers.platform.AgentEntry;
import jade.core.AID;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.domain.FIPAAgentManagement.Property;
import jade.domain.FIPAAgentManagement.SearchConstraints;
import jade.domain.FIPAAgentManagement.ServiceDescription;
import jade.util.leap.Iterator;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * DF descriptions in the FIPA-Agent-Management ontology's SL form, as JADE's DF writes them in
 * subscriptions and their notifications, and the conversions between JADE's descriptions and
 * Concord's yellow-pages entries.
 */
public final class DfSl {
    private DfSl() {
    }

    /** The content of a subscription to the DF: {@code ((iota ?x (result (action df (search dfd constraints)) ?x)))}. */
    public static String subscription(AID df, DFAgentDescription template, SearchConstraints constraints) {
        long max = constraints == null || constraints.getMaxResults() == null ? -1 : constraints.getMaxResults();
        return "((iota ?x (result (action " + aid(df) + " (search " + description(template)
                + " (search-constraints :max-results " + max + "))) ?x)))";
    }

    /** The content of a notification answering that subscription: {@code ((= <its iota> (sequence dfd...)))}. */
    public static String notification(String subscription, List<DFAgentDescription> found) {
        List<?> iota = Sl.find(Sl.parse(subscription), "iota");
        StringBuilder b = new StringBuilder("((= ").append(iota == null ? "(iota ?x (result ?x))" : Sl.write(iota))
                .append(" (sequence");
        for (DFAgentDescription d : found) {
            b.append(' ').append(description(d));
        }
        return b.append(")))").toString();
    }

    /** The template a subscription's content names (the first {@code df-agent-description} in it). */
    public static DFAgentDescription templateOf(String subscription) {
        List<?> d = Sl.find(Sl.parse(subscription), "df-agent-description");
        if (d == null) {
            throw new IllegalArgumentException("no df-agent-description in: " + subscription);
        }
        return description(d);
    }

    /** The descriptions a notification carries: the elements of its sequence (or set). */
    public static DFAgentDescription[] descriptions(String notification) {
        Object e = Sl.parse(notification);
        List<?> eq = Sl.find(e, "=");
        List<?> seq = eq != null && eq.size() > 2 && eq.get(2) instanceof List<?> l ? l : Sl.find(e, "sequence");
        if (seq == null) {
            seq = Sl.find(e, "set");
        }
        List<DFAgentDescription> r = new ArrayList<>();
        if (seq != null) {
            for (Object x : seq) {
                if (x instanceof List<?> l && !l.isEmpty() && "df-agent-description".equalsIgnoreCase(String.valueOf(l.get(0)))) {
                    r.add(description(l));
                }
            }
        }
        return r.toArray(new DFAgentDescription[0]);
    }

    static String aid(AID a) {
        StringBuilder b = new StringBuilder("(agent-identifier :name ").append(Sl.word(a.getName()));
        Iterator it = a.getAllAddresses();
        if (it.hasNext()) {
            b.append(" :addresses (sequence");
            while (it.hasNext()) {
                b.append(' ').append(Sl.word(String.valueOf(it.next())));
            }
            b.append(')');
        }
        return b.append(')').toString();
    }

    /** A description in SL: {@code (df-agent-description :name aid :services (set ...) ...)}, empty slots left out. */
    public static String description(DFAgentDescription d) {
        StringBuilder b = new StringBuilder("(df-agent-description");
        if (d.getName() != null) {
            b.append(" :name ").append(aid(d.getName()));
        }
        Iterator s = d.getAllServices();
        if (s.hasNext()) {
            b.append(" :services (set");
            while (s.hasNext()) {
                b.append(' ').append(service((ServiceDescription) s.next()));
            }
            b.append(')');
        }
        set(b, "protocols", d.getAllProtocols());
        set(b, "ontologies", d.getAllOntologies());
        set(b, "languages", d.getAllLanguages());
        return b.append(')').toString();
    }

    private static String service(ServiceDescription s) {
        StringBuilder b = new StringBuilder("(service-description");
        if (s.getName() != null) {
            b.append(" :name ").append(Sl.word(s.getName()));
        }
        if (s.getType() != null) {
            b.append(" :type ").append(Sl.word(s.getType()));
        }
        set(b, "protocols", s.getAllProtocols());
        set(b, "ontologies", s.getAllOntologies());
        set(b, "languages", s.getAllLanguages());
        if (s.getOwnership() != null) {
            b.append(" :ownership ").append(Sl.word(s.getOwnership()));
        }
        Iterator p = s.getAllProperties();
        if (p.hasNext()) {
            b.append(" :properties (set");
            while (p.hasNext()) {
                Property x = (Property) p.next();
                b.append(" (property :name ").append(Sl.word(x.getName())).append(" :value ")
                        .append(Sl.word(String.valueOf(x.getValue()))).append(')');
            }
            b.append(')');
        }
        return b.append(')').toString();
    }

    private static void set(StringBuilder b, String slot, Iterator it) {
        if (it.hasNext()) {
            b.append(" :").append(slot).append(" (set");
            while (it.hasNext()) {
                b.append(' ').append(Sl.word(String.valueOf(it.next())));
            }
            b.append(')');
        }
    }

    private static DFAgentDescription description(List<?> l) {
        DFAgentDescription d = new DFAgentDescription();
        if (Sl.slot(l, "name") instanceof List<?> a) {
            d.setName(aid(a));
        }
        for (Object s : elements(Sl.slot(l, "services"))) {
            if (s instanceof List<?> sl) {
                d.addServices(service(sl));
            }
        }
        elements(Sl.slot(l, "protocols")).forEach(x -> d.addProtocols(String.valueOf(x)));
        elements(Sl.slot(l, "ontologies")).forEach(x -> d.addOntologies(String.valueOf(x)));
        elements(Sl.slot(l, "languages")).forEach(x -> d.addLanguages(String.valueOf(x)));
        return d;
    }

    private static ServiceDescription service(List<?> l) {
        ServiceDescription s = new ServiceDescription();
        if (Sl.slot(l, "name") instanceof String n) {
            s.setName(n);
        }
        if (Sl.slot(l, "type") instanceof String t) {
            s.setType(t);
        }
        if (Sl.slot(l, "ownership") instanceof String o) {
            s.setOwnership(o);
        }
        elements(Sl.slot(l, "protocols")).forEach(x -> s.addProtocols(String.valueOf(x)));
        elements(Sl.slot(l, "ontologies")).forEach(x -> s.addOntologies(String.valueOf(x)));
        elements(Sl.slot(l, "languages")).forEach(x -> s.addLanguages(String.valueOf(x)));
        for (Object p : elements(Sl.slot(l, "properties"))) {
            if (p instanceof List<?> pl) {
                s.addProperties(new Property(String.valueOf(Sl.slot(pl, "name")), Sl.slot(pl, "value")));
            }
        }
        return s;
    }

    private static AID aid(List<?> l) {
        AID a = new AID(String.valueOf(Sl.slot(l, "name")), AID.ISGUID);
        for (Object x : elements(Sl.slot(l, "addresses"))) {
            a.addAddresses(String.valueOf(x));
        }
        return a;
    }

    /** The elements of {@code (set ...)} or {@code (sequence ...)}; none if absent. */
    private static List<?> elements(Object set) {
        if (set instanceof List<?> l && !l.isEmpty()) {
            return l.subList(1, l.size());
        }
        return List.of();
    }

    /** Concord's yellow-pages services for a JADE description (one per service). */
    public static List<io.concord.layers.platform.ServiceDescription> toConcord(DFAgentDescription dfd) {
        List<io.concord.layers.platform.ServiceDescription> r = new ArrayList<>();
        if (dfd == null) {
            return r;
        }
        for (Iterator it = dfd.getAllServices(); it.hasNext(); ) {
            ServiceDescription s = (ServiceDescription) it.next();
            Map<String, String> props = new TreeMap<>();
            for (Iterator p = s.getAllProperties(); p.hasNext(); ) {
                Property x = (Property) p.next();
                props.put(x.getName(), String.valueOf(x.getValue()));
            }
            r.add(new io.concord.layers.platform.ServiceDescription(s.getType(), s.getName(), props,
                    strings(s.getAllOntologies()), strings(s.getAllLanguages()), strings(s.getAllProtocols())));
        }
        return r;
    }

    private static List<String> strings(Iterator it) {
        List<String> l = new ArrayList<>();
        while (it.hasNext()) {
            l.add((String) it.next());
        }
        return l;
    }

    /** A JADE description of a Concord yellow-pages entry (no services: the agent deregistered). */
    public static DFAgentDescription toJade(AgentEntry e) {
        DFAgentDescription d = new DFAgentDescription();
        d.setName(new AID(Names.decode(e.name()), AID.ISGUID));
        for (io.concord.layers.platform.ServiceDescription s : e.services()) {
            ServiceDescription j = new ServiceDescription();
            j.setType(s.type());
            j.setName(s.name());
            for (Map.Entry<String, String> p : s.properties().entrySet()) {
                j.addProperties(new Property(p.getKey(), p.getValue()));
            }
            s.ontologies().forEach(j::addOntologies);
            s.languages().forEach(j::addLanguages);
            s.protocols().forEach(j::addProtocols);
            d.addServices(j);
        }
        return d;
    }
}

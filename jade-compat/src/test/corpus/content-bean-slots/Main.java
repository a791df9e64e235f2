import jade.content.ContentElement;
import jade.content.ContentManager;
import jade.content.lang.sl.SLCodec;
import jade.content.onto.BasicOntology;
import jade.content.onto.BeanOntology;
import jade.content.onto.basic.Action;
import jade.core.AID;
import jade.lang.acl.ACLMessage;

import java.util.Date;
import java.util.LinkedHashSet;
import java.util.List;

/**
 * A BeanOntology's slot kinds, filled and extracted by a content manager without a platform (as
 * JADE allows): what the SL text is, and what comes back.
 */
public class Main {
    private static ContentManager cm;

    public static void main(String[] args) throws Exception {
        BeanOntology onto = new BeanOntology("gadgets", BasicOntology.getInstance());
        onto.add(Part.class);
        onto.add(Gadget.class);
        onto.add(Move.class);
        onto.add(Fits.class);
        cm = new ContentManager();
        cm.registerLanguage(new SLCodec());
        cm.registerOntology(onto);

        Gadget g = new Gadget();
        g.setName("widget");
        g.setActive(true);
        g.setFlag(Boolean.FALSE);
        g.setWeight(2.25);
        g.setId(12345678901L);
        g.setMade(new Date(1700000000123L));
        g.setTags(new LinkedHashSet<>(List.of("blue")));
        jade.util.leap.List parts = new jade.util.leap.ArrayList();
        parts.add(new Part("bolt"));
        parts.add(new Part("nut \"M6\""));
        g.setParts(parts);
        g.setNumbers(List.of(3, -1, 40));
        g.setAny("anything");
        g.setMain(new Part("frame"));
        g.setSecret("hidden");
        Fits f = new Fits();
        f.setGadget(g);
        f.setPart(new Part("slot"));
        Fits fb = (Fits) roundTrip(f);
        Gadget b = fb.getGadget();
        System.out.println("name=" + b.getName() + " active=" + b.isActive() + " flag=" + b.getFlag() + " weight=" + b.getWeight()
                + " id=" + b.getId() + " made=" + b.getMade().getTime()
                + " tags=" + b.getTags() + " numbers=" + b.getNumbers() + " any=" + b.getAny() + " main=" + b.getMain().getLabel()
                + " secret=" + b.getSecret() + " part=" + fb.getPart().getLabel());
        for (int i = 0; i < b.getParts().size(); i++) {
            System.out.println("  part " + ((Part) b.getParts().get(i)).getLabel());
        }
        // JADE leaves SL's integers Long in a List<Integer> (reading one as an Integer throws): both show it
        Object first = ((List<?>) b.getNumbers()).get(0);
        System.out.println("numbers are " + first.getClass().getSimpleName() + "s");

        Move m = new Move();
        m.setFrom("here");
        m.setTo("there");
        Action a = (Action) roundTrip(new Action(new AID("mover@P", AID.ISGUID), m));
        Move mb = (Move) a.getAction();
        System.out.println("move from " + mb.getFrom() + " to " + mb.getTo() + " by " + a.getActor().getName());
        m.setTo(null);
        mb = (Move) ((Action) roundTrip(new Action(new AID("mover@P", AID.ISGUID), m))).getAction();
        System.out.println("move from " + mb.getFrom() + " to " + mb.getTo());

        Gadget small = new Gadget();
        small.setName("tiny");
        Gadget sb = ((Fits) roundTrip(fits(small))).getGadget();
        System.out.println("tiny: tags=" + sb.getTags() + " parts=" + sb.getParts() + " numbers=" + sb.getNumbers() + " main=" + sb.getMain());

        parts.add(new Part("washer"));
        parts.add(new Part("one too many"));
        try {
            roundTrip(f);
        } catch (Exception e) {
            System.out.println("four parts: " + e.getClass().getSimpleName());
        }
        small.setName(null);
        try {
            roundTrip(fits(small));
        } catch (Exception e) {
            System.out.println("no name: " + e.getClass().getSimpleName());
        }
        System.exit(0);
    }

    private static Fits fits(Gadget g) {
        Fits f = new Fits();
        f.setGadget(g);
        f.setPart(new Part("p"));
        return f;
    }

    private static ContentElement roundTrip(ContentElement ce) throws Exception {
        ACLMessage msg = new ACLMessage(ACLMessage.INFORM);
        msg.setLanguage("fipa-sl");
        msg.setOntology("gadgets");
        cm.fillContent(msg, ce);
        System.out.println(msg.getContent());
        return cm.extractContent(msg);
    }
}
